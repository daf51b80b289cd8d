package net.smc.core.security;

import java.security.SecureRandom;
import java.util.concurrent.TimeUnit;
import net.smc.core.transport.Clock;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;

/**
 * Goal: authentication costs at most 2 µs per heartbeat. After a handshake, a heartbeat-sized
 * payload (48 bytes) is MAC'd by one endpoint and checked by the other ({@code macHeartbeat}: wrap
 * plus unwrap, so the figure is an upper bound of the receiver's cost). For comparison,
 * {@code signedHeartbeat} signs and verifies the same payload with Ed25519, which is why heartbeats
 * use MACs; {@code handshake} prices one whole authenticated key agreement with a new vehicle
 * (making its key and credential included).
 */
@State(Scope.Thread)
@Fork(1)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 5, time = 1)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MICROSECONDS)
public class HeartbeatAuthBench {
    private static final long NOW = 1_700_000_000_000L;
    private static final String MISSION = "bench";

    private final byte[] heartbeat = new byte[48];
    private SigningKey authority;
    private TrustAnchor trust;
    private SecureRandom random;
    private final Clock clock = () -> NOW;
    private SecureEndpoint sender;
    private SecureEndpoint receiver;

    @Setup
    public void setUp() {
        random = new SecureRandom(new byte[] {1, 2, 3});
        authority = SigningKey.generate(random);
        trust = new TrustAnchor(authority.verificationKey(), MISSION);
        sender = endpoint("uav-1");
        receiver = endpoint("cmdr");
        shakeHands(sender, receiver);
        if (!(receiver.unwrap(sender.wrapFor("cmdr", heartbeat)) instanceof Unwrapped.Delivered)) {
            throw new IllegalStateException("a MAC'd heartbeat was not delivered after the handshake");
        }
    }

    private SecureEndpoint endpoint(String id) {
        SigningKey key = SigningKey.generate(random);
        Credential credential = Credential.issue(new Claims(id, key.verificationKey(), MISSION, NOW - 60_000,
                NOW + 3_600_000), authority);
        return SecureEndpoint.builder(new SigningIdentity(key, credential), trust, clock).random(random).build();
    }

    private static void shakeHands(SecureEndpoint a, SecureEndpoint b) {
        byte[] next = a.startHandshake(b.id());
        SecureEndpoint to = b;
        while (next != null) {
            if (!(to.unwrap(next) instanceof Unwrapped.Control step)) {
                throw new IllegalStateException("handshake step refused");
            }
            next = step.reply();
            to = to == a ? b : a;
        }
    }

    @Benchmark
    public Unwrapped macHeartbeat() {
        return receiver.unwrap(sender.wrapFor("cmdr", heartbeat));
    }

    @Benchmark
    public Unwrapped signedHeartbeat() {
        return receiver.unwrap(sender.wrapSigned(heartbeat));
    }

    private int vehicles;

    /** A new vehicle each time (a restarted one on this fixed clock would be refused as a replay). */
    @Benchmark
    public SecureEndpoint handshake() {
        String id = "v" + (++vehicles);
        SecureEndpoint fresh = endpoint(id);
        shakeHands(fresh, receiver);
        receiver.forget(id);
        return fresh;
    }
}
