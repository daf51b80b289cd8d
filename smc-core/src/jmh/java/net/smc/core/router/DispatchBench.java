package net.smc.core.router;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import net.smc.core.message.Envelope;
import net.smc.core.message.Heartbeat;
import net.smc.core.message.MessageType;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;

/**
 * Goal: dispatching a packet with 100 registrations in the router takes 50 ns or less. Twenty
 * subscribers make five registrations each, of all three kinds, over 15 types and 10 sources, with
 * some de-registrations inside aggregates (exclusions); each receiver only counts. {@code source}:
 * {@code known} is a heartbeat from a source with a row (registrations and exclusions for it),
 * which reaches 8 subscribers; {@code unknown} is one from a source nobody named (the type table
 * only), which reaches 1. Set-up prints both counts.
 *
 * <pre>./gradlew :smc-core:jmh -PjmhArgs="DispatchBench"</pre>
 */
@State(Scope.Thread)
@Fork(1)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 5, time = 1)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
public class DispatchBench {
    @Param({"known", "unknown"})
    String source;

    private final MessageRouter router = new MessageRouter();
    private Envelope envelope;

    static final class Counter implements Subscriber {
        long count;

        @Override
        public void receive(Envelope envelope) {
            count++;
        }
    }

    @Setup
    public void setUp() {
        MessageType[] types = MessageType.values();
        List<Counter> roles = new ArrayList<>();
        int registrations = 0;
        for (int r = 0; r < 20; r++) {
            Counter c = new Counter();
            roles.add(c);
            for (int k = 0; k < 5; k++) {
                int n = r * 5 + k;
                MessageType type = types[n % types.length];
                String src = "uav" + n % 10;
                switch (n % 3) {
                    case 0 -> router.register(c, type);
                    case 1 -> router.register(c, src);
                    default -> router.register(c, type, src);
                }
                registrations++;
            }
        }
        // De-registrations inside aggregates: exclusion-table entries for the measured packet's source.
        router.deregister(roles.get(0), MessageType.HEARTBEAT, "uav3");
        router.deregister(roles.get(5), MessageType.HEARTBEAT, "uav3");
        router.register(roles.get(7), MessageType.HEARTBEAT);
        router.register(roles.get(9), "uav3");
        // A sender string that is equal to, not the same object as, the registered one (as after decoding).
        String sender = source.equals("known") ? new String("uav3".toCharArray()) : "stranger";
        envelope = new Envelope(sender, 1, new Heartbeat("relay", 1, 0));
        int receivers = router.dispatch(envelope);
        System.out.println("\n" + registrations + " registrations; a heartbeat from " + sender + " reaches "
                + receivers + " subscribers");
    }

    @Benchmark
    public int dispatch() {
        return router.dispatch(envelope);
    }
}
