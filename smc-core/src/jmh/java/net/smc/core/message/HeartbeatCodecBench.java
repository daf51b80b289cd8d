package net.smc.core.message;

import java.nio.ByteBuffer;
import java.util.concurrent.TimeUnit;
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
 * Goal: encode plus decode of a heartbeat at 5,000,000 per second or more on one core, allocating
 * in the steady state nothing but what the decoded message is made of (check with {@code -prof gc}:
 * {@code gc.alloc.rate.norm} should be 80 bytes with compressed oops: the {@code Heartbeat} (32),
 * the {@code Envelope} (32) and the {@code Decoded} result (16); the sender and role strings come
 * from the decoder's name cache, and encoding allocates nothing). {@code encode} and
 * {@code decode} alone show where the time goes.
 *
 * <pre>./gradlew :smc-core:jmh -PjmhArgs="HeartbeatCodecBench -prof gc"</pre>
 */
@State(Scope.Thread)
@Fork(1)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 5, time = 1)
@BenchmarkMode(Mode.Throughput)
@OutputTimeUnit(TimeUnit.SECONDS)
public class HeartbeatCodecBench {
    private final MessageEncoder encoder = new MessageEncoder();
    private final MessageDecoder decoder = new MessageDecoder(() -> 0L);
    private final ByteBuffer buffer = ByteBuffer.allocate(WireFormat.MAX_DATAGRAM);
    private final ByteBuffer encoded = ByteBuffer.allocate(WireFormat.MAX_DATAGRAM);
    private Envelope heartbeat;

    @Setup
    public void setUp() {
        heartbeat = new Envelope("uav-0017", 123_456_789L, new Heartbeat("relay", 42, 1));
        encoder.encode(heartbeat, encoded);
        encoded.flip();
        if (!(decoder.decode(encoded) instanceof DecodeResult.Decoded d) || !d.envelope().equals(heartbeat)) {
            throw new IllegalStateException("the heartbeat does not round-trip");
        }
    }

    @Benchmark
    public DecodeResult encodeDecode() {
        buffer.clear();
        encoder.encode(heartbeat, buffer);
        buffer.flip();
        return decoder.decode(buffer);
    }

    @Benchmark
    public int encode() {
        buffer.clear();
        return encoder.encode(heartbeat, buffer);
    }

    @Benchmark
    public DecodeResult decode() {
        return decoder.decode(encoded);
    }
}
