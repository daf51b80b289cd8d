package net.smc.core.message;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.zip.Adler32;
import java.util.zip.Deflater;

import org.junit.jupiter.api.Test;

import net.smc.core.wire.ByteWriter;

/** A policy reply's text on the wire: deflated over the dictionary when that is shorter, and inflated with bounds. */
class PolicyTextCodingTest {
    /** Two generated managers' role-missions ({@link Samples#MANAGER_ROLE_MISSION} twice). */
    private static final String MISSION = Samples.MANAGER_ROLE_MISSION.repeat(2);

    /** Payload bytes before the text: inReplyTo 8, URI "u" 1 + 1, version 4. */
    private static final int BEFORE_TEXT = 8 + 2 + 4;
    private final Codec codec = new Codec();

    private static Raw reply() {
        return Raw.of(MessageType.POLICY_REPLY).i64(1).str8("u").i32(1);
    }

    private static byte[] zlib(byte[] in, byte[] dictionary) {
        return zlib(in, dictionary, 9);
    }

    private static byte[] zlib(byte[] in, byte[] dictionary, int level) {
        Deflater d = new Deflater(level);
        if (dictionary != null) {
            d.setDictionary(dictionary);
        }
        d.setInput(in);
        d.finish();
        byte[] out = new byte[in.length + 64];
        int n = d.deflate(out);
        d.end();
        return Arrays.copyOf(out, n);
    }

    private DecodeResult.Rejected reject(byte[] datagram, RejectReason reason, String detail) {
        DecodeResult.Rejected r = Codec.rejected(codec.decode(datagram));
        assertEquals(detail, r.detail());
        assertEquals(reason, r.reason());
        return r;
    }

    @Test
    void aPolicyFile_roundTrips_inFewerWireBytesThanItsText() {
        Envelope e = new Envelope("b0l1n0", 7, new PolicyReply(3, "policy:/roles/b0l1/mission", 1, MISSION));
        byte[] d = codec.datagram(e);
        int text = MISSION.getBytes(StandardCharsets.UTF_8).length;
        assertTrue(text > 1_500, text + " bytes");
        // Header 13 + sender 6, the payload before the text 8 + 27 + 4, length 2 and coding 1.
        int textAt = WireFormat.FIXED_HEADER + 6 + 8 + 27 + 4;
        assertEquals(WireFormat.POLICY_TEXT_DEFLATE_DICTIONARY, d[textAt + 2]);
        int deflated = (d[textAt + 3] & 0xFF) << 8 | d[textAt + 4] & 0xFF;
        assertEquals(d.length, textAt + 5 + deflated);
        assertTrue(deflated < text / 5, deflated + " bytes for " + text);
        assertEquals(e, codec.roundTrip(e));
        assertEquals(e, Codec.decoded(codec.decode(d)));
    }

    @Test
    void aLargeFile_fitsFewerDatagramsThanItsText() {
        Envelope e = new Envelope("uav1", 77, new PolicyReply(5, "policy:/roles/relay", 2, MISSION.repeat(10)));
        assertEquals(1, codec.encode(e).size());  // 15,940 bytes of text, 12 fragments uncompressed
        assertEquals(e, codec.roundTrip(e));
    }

    @Test
    void aShortText_goesAsItIs() {
        String text = "p := root/factory/ecapolicy create.";
        byte[] d = codec.datagram(new Envelope("uav1", 7, new PolicyReply(1, "u", 1, text)));
        byte[] expected = reply().u16(text.length()).u8(WireFormat.POLICY_TEXT_PLAIN)
                .raw(text.getBytes(StandardCharsets.UTF_8)).datagram();
        assertEquals(Arrays.toString(expected), Arrays.toString(d));
        assertEquals(text, ((PolicyReply) Codec.decoded(codec.decode(d)).body()).text());
    }

    @Test
    void aTextDeflateCannotShorten_goesAsItIs() {
        java.util.Random random = new java.util.Random(7);
        StringBuilder sb = new StringBuilder();
        for (int i = 0; i < 100; i++) {
            sb.append((char) (33 + random.nextInt(94)));
        }
        Envelope e = new Envelope("uav1", 7, new PolicyReply(1, "u", 1, sb.toString()));
        byte[] d = codec.datagram(e);
        assertEquals(WireFormat.POLICY_TEXT_PLAIN, d[WireFormat.FIXED_HEADER + 4 + BEFORE_TEXT + 2]);
        assertEquals(WireFormat.FIXED_HEADER + 4 + BEFORE_TEXT + 3 + 100, d.length);
        assertEquals(e, Codec.decoded(codec.decode(d)));
    }

    @Test
    void aStreamFromAnotherDeflater_isRead_overTheDictionaryOrWithout() {
        byte[] text = MISSION.getBytes(StandardCharsets.UTF_8);
        byte[] z = zlib(text, null);
        PolicyReply r = (PolicyReply) Codec.decoded(codec.decode(reply().u16(text.length)
                .u8(WireFormat.POLICY_TEXT_DEFLATE).u16(z.length).raw(z).datagram())).body();
        assertEquals(MISSION, r.text());
        byte[] zd = zlib(text, PolicyDictionary.BYTES);
        r = (PolicyReply) Codec.decoded(codec.decode(reply().u16(text.length)
                .u8(WireFormat.POLICY_TEXT_DEFLATE_DICTIONARY).u16(zd.length).raw(zd).datagram())).body();
        assertEquals(MISSION, r.text());
    }

    /**
     * The dictionary is part of the wire format: a stream names it by its Adler-32, so a byte of it
     * changed is a new format, which this pins (change the number only with the format).
     */
    @Test
    void theDictionary_isPinnedByItsAdler32() {
        assertEquals("24a0cae6", String.format("%08x", PolicyDictionary.ID), PolicyDictionary.BYTES.length + " bytes");
    }

    /**
     * What the dictionary buys on the project's own policy files (the reconnaissance mission's roles
     * and the boot file): fewer bytes on the radio than DEFLATE alone. Its phrases are the
     * architecture's vocabulary, not these files' text, so the gain on them is a modest one.
     */
    @Test
    void theProjectsPolicyFiles_takeFewerBytesOverTheDictionary() throws Exception {
        Path policies = Path.of(System.getProperty("smc.repo.dir", "../policies"));
        long plain = 0;
        long alone = 0;
        long over = 0;
        int files = 0;
        try (var walk = Files.walk(policies)) {
            for (Path f : walk.filter(x -> x.toString().endsWith(".p2")).toList()) {
                byte[] text = Files.readAllBytes(f);
                ByteWriter w = ByteWriter.growing(1_024, 1 << 20, IllegalStateException::new);
                PolicyTextCoding.write(new String(text, StandardCharsets.UTF_8), w);
                assertEquals(WireFormat.POLICY_TEXT_DEFLATE_DICTIONARY, w.array()[2], f.toString());
                plain += text.length;
                alone += zlib(text, null, 6).length;
                over += w.position() - 5;
                files++;
            }
        }
        assertTrue(files >= 20, files + " policy files under " + policies.toAbsolutePath());
        assertTrue(over < alone * 85 / 100, over + " bytes over the dictionary, " + alone + " without, " + plain + " of text");
    }

    @Test
    void aBomb_isRefusedAsOversized_withoutInflatingIt() {
        byte[] z = zlib(new byte[1_000_000], null);  // 1 MB of zeros in about a kilobyte
        reject(reply().u16(100).u8(WireFormat.POLICY_TEXT_DEFLATE).u16(z.length).raw(z).datagram(),
                RejectReason.OVERSIZED, "POLICY_REPLY from 'uav1' (id 7): text inflates to more than the 100 bytes"
                        + " it declares");
        reject(reply().u16(WireFormat.MAX_POLICY_TEXT).u8(WireFormat.POLICY_TEXT_DEFLATE).u16(z.length).raw(z)
                .datagram(), RejectReason.OVERSIZED, "POLICY_REPLY from 'uav1' (id 7): text inflates to more than the"
                + " 65000 bytes it declares");
    }

    @Test
    void aDeclaredLengthOverTheLimit_isRefusedBeforeInflating() {
        byte[] z = zlib(new byte[65_001], null);
        reject(reply().u16(65_001).u8(WireFormat.POLICY_TEXT_DEFLATE).u16(z.length).raw(z).datagram(),
                RejectReason.OVERSIZED, "POLICY_REPLY from 'uav1' (id 7): text is 65001 bytes; at most 65000 are"
                        + " allowed");
    }

    @Test
    void aStreamShorterThanDeclared_isRefused() {
        byte[] text = MISSION.getBytes(StandardCharsets.UTF_8);
        byte[] z = zlib(text, null);
        reject(reply().u16(text.length + 1).u8(WireFormat.POLICY_TEXT_DEFLATE).u16(z.length).raw(z).datagram(),
                RejectReason.MALFORMED, "POLICY_REPLY from 'uav1' (id 7): text inflates to " + text.length + " bytes, not"
                        + " the " + (text.length + 1) + " it declares");
        byte[] cut = Arrays.copyOf(z, z.length - 10);
        DecodeResult.Rejected r = Codec.rejected(codec.decode(reply().u16(text.length)
                .u8(WireFormat.POLICY_TEXT_DEFLATE).u16(cut.length).raw(cut).datagram()));
        assertEquals(RejectReason.TRUNCATED, r.reason());
        assertTrue(r.detail().matches("POLICY_REPLY from 'uav1' \\(id 7\\): the DEFLATE stream of text ends after"
                + " \\d+ of the " + text.length + " bytes it declares"), r.detail());
    }

    @Test
    void corruptData_isRefused() {
        byte[] text = MISSION.getBytes(StandardCharsets.UTF_8);
        byte[] z = zlib(text, null);
        byte[] bad = z.clone();
        bad[z.length - 1] ^= 1;  // the checksum
        reject(reply().u16(text.length).u8(WireFormat.POLICY_TEXT_DEFLATE).u16(bad.length).raw(bad).datagram(),
                RejectReason.MALFORMED, "POLICY_REPLY from 'uav1' (id 7): text is not a valid DEFLATE stream"
                        + " (incorrect data check)");
        byte[] trailing = Arrays.copyOf(z, z.length + 2);
        reject(reply().u16(text.length).u8(WireFormat.POLICY_TEXT_DEFLATE).u16(trailing.length).raw(trailing)
                .datagram(), RejectReason.MALFORMED, "POLICY_REPLY from 'uav1' (id 7): 2 bytes follow the DEFLATE"
                + " stream of text");
        reject(reply().u16(text.length).u8(3).u16(z.length).raw(z).datagram(), RejectReason.MALFORMED,
                "POLICY_REPLY from 'uav1' (id 7): the coding of text is 3; it is 0 (plain), 1 (DEFLATE) or 2"
                        + " (DEFLATE over the dictionary)");
        byte[] withDictionary = zlib(text, PolicyDictionary.BYTES);
        reject(reply().u16(text.length).u8(WireFormat.POLICY_TEXT_DEFLATE).u16(withDictionary.length)
                .raw(withDictionary).datagram(), RejectReason.MALFORMED, "POLICY_REPLY from 'uav1' (id 7): text is a"
                + " DEFLATE stream that needs a preset dictionary; its coding (1) uses none");
        byte[] otherDictionary = zlib(text, "root/factory/".getBytes(StandardCharsets.UTF_8));
        Adler32 other = new Adler32();
        other.update("root/factory/".getBytes(StandardCharsets.UTF_8));
        reject(reply().u16(text.length).u8(WireFormat.POLICY_TEXT_DEFLATE_DICTIONARY).u16(otherDictionary.length)
                .raw(otherDictionary).datagram(), RejectReason.MALFORMED, String.format("POLICY_REPLY from 'uav1'"
                + " (id 7): text is a DEFLATE stream over the dictionary %08x; this format's is 24a0cae6", other.getValue()));
        reject(reply().u16(text.length).u8(WireFormat.POLICY_TEXT_DEFLATE_DICTIONARY).u16(z.length).raw(z).datagram(),
                RejectReason.MALFORMED, "POLICY_REPLY from 'uav1' (id 7): text is a DEFLATE stream that names no"
                        + " preset dictionary; its coding (2) uses the dictionary of PonderTalk phrases");
    }

    @Test
    void everySingleBitFlipOfADeflatedText_isRefused_orReadsTheSameText() {
        Envelope e = new Envelope("uav1", 3, new PolicyReply(1, "u", 1, MISSION));
        byte[] d = codec.datagram(e);
        int refused = 0;
        int textAt = WireFormat.FIXED_HEADER + 4 + BEFORE_TEXT;
        for (int bit = textAt * 8; bit < d.length * 8; bit++) {
            byte[] flipped = d.clone();
            flipped[bit >>> 3] ^= (byte) (1 << (bit & 7));
            DecodeResult r = new MessageDecoder(() -> 0).decode(flipped);
            if (r instanceof DecodeResult.Rejected) {
                refused++;
            } else {
                // A bit the inflater never reads (padding after the last block), or a back-reference
                // turned into another to the same bytes: the same text.
                assertEquals(e, Codec.decoded(r), "a flip of bit " + bit);
            }
        }
        int bits = (d.length - textAt) * 8;
        assertTrue(refused >= bits * 99 / 100, refused + " of " + bits + " flips refused");
    }
}
