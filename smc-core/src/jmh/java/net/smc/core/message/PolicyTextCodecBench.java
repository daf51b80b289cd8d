package net.smc.core.message;

import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.util.concurrent.TimeUnit;
import java.util.zip.DataFormatException;
import java.util.zip.Deflater;
import java.util.zip.Inflater;

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
import org.openjdk.jmh.annotations.TearDown;
import org.openjdk.jmh.annotations.Warmup;

/**
 * What the preset dictionary ({@link PolicyDictionary}) costs a policy file's sender and receiver:
 * DEFLATE at level 6 of one role file with and without the dictionary, inflating it back each way,
 * and the codec's whole encode and decode of the {@code PolicyReply} that carries it (which deflates
 * over the dictionary). The files are a generated manager's role-mission (797 bytes) and a
 * reconnaissance-style authorisation file; the bytes each way are printed at set-up.
 *
 * <pre>./gradlew :smc-core:jmh -PjmhArgs="PolicyTextCodecBench"</pre>
 */
@State(Scope.Thread)
@Fork(1)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 5, time = 1)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MICROSECONDS)
public class PolicyTextCodecBench {
    private static final String MANAGER = Samples.MANAGER_ROLE_MISSION;

    private static final String AUTHORISATIONS = """
            // Authorisations of the relay: the surveyor that manages it may use its management
            // operations and its exported task operations.

            (root/role/relay/peers has: "surveyor") ifFalse: [
                root/role/relay/peers at: "surveyor" put: root/factory/domain create].
            a := root/factory/authpolicy subject: root/role/relay/peers/surveyor action: "*"
                    target: root/role/relay focus: "st".
            root/role/relay/auth at: "managerManages" put: a.
            """;

    @Param({"manager", "authorisations"})
    public String file;

    private byte[] text;
    private final Deflater deflater = new Deflater(6);
    private final Inflater inflater = new Inflater();
    private final byte[] out = new byte[8_192];
    private byte[] alone;
    private byte[] over;
    private final MessageEncoder encoder = new MessageEncoder();
    private final MessageDecoder decoder = new MessageDecoder(() -> 0L);
    private final ByteBuffer buffer = ByteBuffer.allocate(WireFormat.MAX_DATAGRAM);
    private Envelope reply;

    @Setup
    public void setUp() throws DataFormatException {
        String t = file.equals("manager") ? MANAGER : AUTHORISATIONS;
        text = t.getBytes(StandardCharsets.UTF_8);
        alone = java.util.Arrays.copyOf(out, deflateAlone());
        over = java.util.Arrays.copyOf(out, deflateOverDictionary());
        if (inflateAlone() != text.length || inflateOverDictionary() != text.length) {
            throw new IllegalStateException("the file does not round-trip");
        }
        reply = new Envelope("b0l1n0", 9, new PolicyReply(8, "policy:/roles/b0l1/mission", 1, t));
        System.out.printf("%n%s: %d bytes of text, deflated %d alone, %d over the dictionary%n", file, text.length,
                alone.length, over.length);
    }

    @TearDown
    public void tearDown() {
        deflater.end();
        inflater.end();
    }

    @Benchmark
    public int deflateAlone() {
        deflater.reset();
        deflater.setInput(text);
        deflater.finish();
        return deflater.deflate(out);
    }

    @Benchmark
    public int deflateOverDictionary() {
        deflater.reset();
        deflater.setDictionary(PolicyDictionary.BYTES);
        deflater.setInput(text);
        deflater.finish();
        return deflater.deflate(out);
    }

    @Benchmark
    public int inflateAlone() throws DataFormatException {
        inflater.reset();
        inflater.setInput(alone);
        return inflater.inflate(out);
    }

    @Benchmark
    public int inflateOverDictionary() throws DataFormatException {
        inflater.reset();
        inflater.setInput(over);
        inflater.inflate(out);
        inflater.setDictionary(PolicyDictionary.BYTES);
        return inflater.inflate(out);
    }

    @Benchmark
    public DecodeResult encodeDecodeReply() {
        buffer.clear();
        encoder.encode(reply, buffer);
        buffer.flip();
        return decoder.decode(buffer);
    }
}
