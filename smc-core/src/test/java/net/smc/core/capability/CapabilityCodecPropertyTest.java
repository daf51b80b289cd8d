package net.smc.core.capability;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.fail;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import java.util.TreeSet;
import org.junit.jupiter.api.Test;

/**
 * Properties of the wire form over seeded random values: every description round-trips exactly;
 * every damaged input (truncated, bit-flipped, random) either decodes to something that re-encodes
 * to the very same bytes, or fails with {@link CapabilityFormatException}, never any other
 * exception and never an allocation larger than the input. A failure prints its seed.
 */
class CapabilityCodecPropertyTest {
    private static final int CASES = 300;
    private static final CapabilityCodec CODEC = CapabilityCodec.STANDARD;

    /** Characters from every UTF-8 length: ASCII, Latin, CJK, and a supplementary-plane emoji. */
    private static final String[] ALPHABET = {"a", "Z", "_", "0", " ", "é", "ß", "中", "文", "\uD83D\uDE80", "\u0000"};

    private static String string(Random r, int maxChars) {
        StringBuilder s = new StringBuilder();
        int n = r.nextInt(maxChars + 1);
        for (int i = 0; i < n; i++) {
            s.append(ALPHABET[r.nextInt(ALPHABET.length)]);
        }
        return s.toString();
    }

    private static TreeSet<String> set(Random r, int max) {
        TreeSet<String> s = new TreeSet<>();
        int n = r.nextInt(max + 1);
        for (int i = 0; i < n; i++) {
            s.add(string(r, 12));
        }
        return s;
    }

    private static List<String> list(Random r, int max) {
        List<String> l = new ArrayList<>();
        int n = r.nextInt(max + 1);
        for (int i = 0; i < n; i++) {
            l.add(string(r, 10));
        }
        return l;
    }

    static CapabilityDescription description(Random r) {
        List<TaskDescription> tasks = new ArrayList<>();
        int taskCount = r.nextInt(5);
        for (int t = 0; t < taskCount; t++) {
            List<OperationDescription> ops = new ArrayList<>();
            int opCount = r.nextInt(5);
            for (int o = 0; o < opCount; o++) {
                ops.add(new OperationDescription(string(r, 12), list(r, 4)));
            }
            List<EventDescription> events = new ArrayList<>();
            int eventCount = r.nextInt(4);
            for (int e = 0; e < eventCount; e++) {
                List<EventDescription.Attribute> attributes = new ArrayList<>();
                int attrCount = r.nextInt(4);
                for (int a = 0; a < attrCount; a++) {
                    attributes.add(new EventDescription.Attribute(string(r, 8), string(r, 8)));
                }
                events.add(new EventDescription(string(r, 12), attributes));
            }
            tasks.add(new TaskDescription(string(r, 12), ops, events));
        }
        return new CapabilityDescription(string(r, 16), set(r, 6), tasks);
    }

    static CapabilitySummary summary(Random r) {
        return new CapabilitySummary(string(r, 16), set(r, 6), set(r, 6));
    }

    @Test
    void randomDescriptions_roundTripExactly() throws Exception {
        for (int seed = 0; seed < CASES; seed++) {
            CapabilityDescription d = description(new Random(seed));
            byte[] bytes = CODEC.encode(d);
            assertEquals(d, CODEC.decodeDescription(bytes), "seed " + seed);
            assertArrayEquals(bytes, CODEC.encode(CODEC.decodeDescription(bytes)), "seed " + seed);
        }
    }

    @Test
    void randomSummaries_roundTripExactlyAndMatchTheirDescriptions() throws Exception {
        for (int seed = 0; seed < CASES; seed++) {
            CapabilitySummary s = summary(new Random(seed));
            assertEquals(s, CODEC.decodeSummary(CODEC.encode(s)), "seed " + seed);
            CapabilityDescription d = description(new Random(seed));
            CapabilitySummary fromWire = CODEC.decodeSummary(CODEC.encode(d.summary()));
            assertEquals(true, fromWire.matches(CODEC.decodeDescription(CODEC.encode(d))), "seed " + seed);
        }
    }

    @Test
    void everyTruncation_isAFormatError() {
        for (int seed = 0; seed < 60; seed++) {
            byte[] whole = CODEC.encode(description(new Random(seed)));
            for (int length = 0; length < whole.length; length++) {
                byte[] cut = Arrays.copyOf(whole, length);
                expectFormatError(cut, true, "seed " + seed + " length " + length);
            }
            byte[] summary = CODEC.encode(summary(new Random(seed)));
            for (int length = 0; length < summary.length; length++) {
                expectFormatError(Arrays.copyOf(summary, length), false, "summary seed " + seed + " length " + length);
            }
        }
    }

    @Test
    void bitFlips_giveAFormatErrorOrACanonicalForm() {
        for (int seed = 0; seed < CASES; seed++) {
            Random r = new Random(seed);
            boolean full = r.nextBoolean();
            byte[] bytes = full ? CODEC.encode(description(r)) : CODEC.encode(summary(r));
            int flips = 1 + r.nextInt(3);
            for (int i = 0; i < flips; i++) {
                int bit = r.nextInt(bytes.length * 8);
                bytes[bit / 8] ^= (byte) (1 << (bit % 8));
            }
            expectFormatErrorOrCanonical(bytes, full, "seed " + seed);
        }
    }

    @Test
    void randomBytes_giveAFormatErrorOrACanonicalForm() {
        for (int seed = 0; seed < CASES; seed++) {
            Random r = new Random(seed);
            byte[] bytes = new byte[r.nextInt(64)];
            r.nextBytes(bytes);
            if (bytes.length >= 2) {
                bytes[0] = (byte) (r.nextBoolean() ? 'S' : 'D');   // get past the header most of the time
                bytes[1] = 1;
            }
            expectFormatErrorOrCanonical(bytes, bytes.length > 0 && bytes[0] == 'D', "seed " + seed);
        }
    }

    @Test
    void hugeDeclaredSizes_withLargeLimits_failWithoutAllocating() {
        CapabilityCodec wide = new CapabilityCodec(new CapabilityCodec.Limits(0xffff, 0xffff, Integer.MAX_VALUE));
        byte[] bytes = {'D', 1, 0, 0, 0, 0, (byte) 0xff, (byte) 0xff, 0, 0, (byte) 0xff, (byte) 0xff};
        try {
            wide.decodeDescription(bytes);
            fail("decoded a form that declares 65535 tasks in 12 bytes");
        } catch (CapabilityFormatException expected) {
            assertEquals(true, expected.getMessage().contains("truncated"), expected.getMessage());
        }
    }

    /** A proper prefix of a self-delimiting form never decodes. */
    private static void expectFormatError(byte[] bytes, boolean full, String label) {
        Object decoded;
        try {
            decoded = full ? CODEC.decodeDescription(bytes) : CODEC.decodeSummary(bytes);
        } catch (CapabilityFormatException expected) {
            assertEquals(true, expected.getMessage().contains("truncated"), label + ": " + expected.getMessage());
            return;
        } catch (RuntimeException | Error e) {
            throw new AssertionError(label + ": " + e + " escaped instead of a CapabilityFormatException", e);
        }
        fail(label + ": a truncated form decoded to " + decoded);
    }

    /** Decoding either fails with the declared exception, or yields a value that re-encodes to the input. */
    private static void expectFormatErrorOrCanonical(byte[] bytes, boolean full, String label) {
        byte[] again;
        try {
            again = full ? CODEC.encode(CODEC.decodeDescription(bytes)) : CODEC.encode(CODEC.decodeSummary(bytes));
        } catch (CapabilityFormatException expected) {
            if (expected.getMessage() == null || expected.getMessage().isEmpty()) {
                fail(label + ": a format error without a message");
            }
            return;
        } catch (RuntimeException | Error e) {
            throw new AssertionError(label + ": " + e + " escaped instead of a CapabilityFormatException", e);
        }
        assertArrayEquals(bytes, again, label + ": decoded, so it must be canonical");
    }
}
