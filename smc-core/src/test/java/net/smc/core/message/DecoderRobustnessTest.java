package net.smc.core.message;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * The decoder against damaged and hostile input: it never throws, never reports an internal
 * error, and whatever it accepts is exactly what the bytes say (re-encoding gives the same bytes).
 */
class DecoderRobustnessTest {
    private final Codec codec = new Codec();

    /** One datagram of each ordinary and boundary message, from a short and a long sender. */
    private List<byte[]> validDatagrams() {
        List<byte[]> all = new ArrayList<>();
        long id = 1;
        for (String sender : List.of("uav1", "\uD83D\uDE81".repeat(16))) {
            for (Message m : Samples.ordinary()) {
                all.add(codec.datagram(new Envelope(sender, id++, m)));
            }
            for (Message m : Samples.boundaries()) {
                all.add(codec.datagram(new Envelope(sender, id++, m)));
            }
        }
        return all;
    }

    private DecodeResult decodeChecked(MessageDecoder decoder, byte[] input) {
        DecodeResult r;
        try {
            r = decoder.decode(input);
        } catch (RuntimeException e) {
            return fail("decode threw on " + Arrays.toString(input), e);
        }
        codec.checkInvariants(input, r);
        return r;
    }

    @Test
    void everyPrefixOfAValidDatagram_isTruncated() {
        for (byte[] d : validDatagrams()) {
            for (int len = 0; len < d.length; len++) {
                DecodeResult r = decodeChecked(codec.decoder, Arrays.copyOf(d, len));
                assertEquals(RejectReason.TRUNCATED, Codec.rejected(r).reason(), () -> Codec.rejected(r).detail());
            }
        }
    }

    @Test
    void everySingleBitFlip_isRejectedOrAnotherValidMessage() {
        int rejected = 0;
        int decoded = 0;
        for (byte[] d : validDatagrams()) {
            for (int bit = 0; bit < d.length * 8; bit++) {
                byte[] flipped = d.clone();
                flipped[bit >>> 3] ^= (byte) (1 << (bit & 7));
                DecodeResult r = decodeChecked(codec.decoder, flipped);
                if (r instanceof DecodeResult.Decoded) {
                    decoded++;
                } else if (r instanceof DecodeResult.Rejected) {
                    rejected++;
                } else {
                    fail("a flip of bit " + bit + " gave " + r);
                }
            }
        }
        assertTrue(rejected > 0 && decoded > 0, rejected + " rejected, " + decoded + " decoded");
    }

    @Test
    void everySingleBitFlipOfAFragment_isRejectedOrPending() {
        Envelope e = new Envelope("uav1", 3, Samples.bulk("a", 3_000));
        for (byte[] d : codec.encode(e)) {
            for (int bit = 0; bit < d.length * 8; bit++) {
                byte[] flipped = d.clone();
                flipped[bit >>> 3] ^= (byte) (1 << (bit & 7));
                MessageDecoder fresh = new MessageDecoder(() -> 0);
                DecodeResult r = decodeChecked(fresh, flipped);
                assertTrue(r instanceof DecodeResult.Rejected || r instanceof DecodeResult.FragmentPending,
                        () -> "a flip gave " + r);
            }
        }
    }

    @Test
    void aFlippedFragmentAmongItsSiblings_neverBreaksTheDecoder() {
        Envelope e = new Envelope("uav1", 3, Samples.bulk("a", 3_000));
        List<byte[]> fragments = codec.encode(e);
        Random random = new Random(5);
        for (int n = 0; n < 2_000; n++) {
            MessageDecoder decoder = new MessageDecoder(() -> 0);
            int victim = random.nextInt(fragments.size());
            for (int i = 0; i < fragments.size(); i++) {
                byte[] d = fragments.get(i).clone();
                if (i == victim) {
                    int bit = random.nextInt(d.length * 8);
                    d[bit >>> 3] ^= (byte) (1 << (bit & 7));
                }
                DecodeResult r = decodeChecked(decoder, d);
                if (r instanceof DecodeResult.Decoded decoded && !decoded.envelope().equals(e)) {
                    // A flip inside the chunk changes a string; anything else would have been caught.
                    assertEquals(e.sender(), decoded.envelope().sender());
                }
            }
        }
    }

    @Test
    void randomInput_100k_neverBreaksTheDecoder() {
        Random random = new Random(20240611);
        List<byte[]> valid = validDatagrams();
        MessageDecoder decoder = new MessageDecoder(() -> 0, new ReassemblySettings(1_000, 100_000, 4));
        int[] outcomes = new int[3];
        for (int n = 0; n < 100_000; n++) {
            byte[] input = switch (n % 4) {
                case 0 -> randomBytes(random, random.nextInt(1_500));
                case 1 -> mutate(random, valid.get(random.nextInt(valid.size())));
                case 2 -> validHeaderRandomPayload(random);
                default -> randomFragment(random);
            };
            DecodeResult r = decodeChecked(decoder, input);
            outcomes[r instanceof DecodeResult.Decoded ? 0 : r instanceof DecodeResult.FragmentPending ? 1 : 2]++;
            assertTrue(decoder.reassembliesInProgress() <= 4);
            assertTrue(decoder.bufferedBytes() >= 0 && decoder.bufferedBytes() <= 100_000);
        }
        assertEquals(100_000, decoder.decoded() + decoder.fragmentsPending()
                + decoder.rejected());
        assertTrue(outcomes[0] > 0 && outcomes[1] > 0 && outcomes[2] > 0, Arrays.toString(outcomes));
    }

    private static byte[] randomBytes(Random random, int length) {
        byte[] b = new byte[length];
        random.nextBytes(b);
        return b;
    }

    /** A valid datagram with a few bytes changed, inserted, removed or a tail cut off. */
    private static byte[] mutate(Random random, byte[] d) {
        byte[] b = d.clone();
        int edits = 1 + random.nextInt(4);
        for (int i = 0; i < edits && b.length > 0; i++) {
            int at = random.nextInt(b.length);
            switch (random.nextInt(4)) {
                case 0 -> b[at] = (byte) random.nextInt(256);
                case 1 -> b[at] = (byte) (random.nextBoolean() ? 0 : 0xFF);
                case 2 -> b = Arrays.copyOf(b, at);
                default -> {
                    byte[] longer = new byte[b.length + 1];
                    System.arraycopy(b, 0, longer, 0, at);
                    longer[at] = (byte) random.nextInt(256);
                    System.arraycopy(b, at, longer, at + 1, b.length - at);
                    b = longer;
                }
            }
        }
        return b;
    }

    /** A correct header of a random message type in front of random (often short, often small-valued) bytes. */
    private static byte[] validHeaderRandomPayload(Random random) {
        MessageType type = MessageType.values()[random.nextInt(MessageType.values().length)];
        Raw raw = Raw.of(type);
        int len = random.nextInt(random.nextBoolean() ? 24 : 300);
        for (int i = 0; i < len; i++) {
            raw.u8(random.nextInt(4) == 0 ? random.nextInt(256) : random.nextInt(8));
        }
        return raw.datagram();
    }

    /** A well-formed fragment frame of random message, index and count, often colliding with earlier ones. */
    private static byte[] randomFragment(Random random) {
        int count = 2 + random.nextInt(4);
        int total = count * (1 + random.nextInt(40));
        int index = random.nextInt(count);
        int chunk = Fragmenter.chunkLength(index, count, total);
        MessageType type = random.nextBoolean() ? MessageType.HEARTBEAT : MessageType.ROLE_EVENT;
        Raw raw = new Raw(WireFormat.FRAGMENT_CODE).u8(type.code()).u16(index).u16(count).i32(total);
        for (int i = 0; i < chunk; i++) {
            raw.u8(random.nextInt(6));
        }
        raw.id = random.nextInt(8);
        return raw.datagram();
    }
}
