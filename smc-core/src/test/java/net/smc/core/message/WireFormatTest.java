package net.smc.core.message;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;

import java.util.HexFormat;
import java.util.List;
import org.junit.jupiter.api.Test;

/** Pins the bytes of the format, so that a change to it is a deliberate one (and a new version). */
class WireFormatTest {
    private final Codec codec = new Codec();

    private static String hex(byte[] b) {
        return HexFormat.ofDelimiter(" ").formatHex(b);
    }

    @Test
    void heartbeat_isHeaderThenRoleThenVarintEpochStateAndStatusVersion() {
        byte[] d = codec.datagram(new Envelope("uav1", 7, new Heartbeat("relay", 42, 1, 300)));
        assertEquals("53 4d 02 09 04 75 61 76 31 00 00 00 00 00 00 00 07 "   // magic, version, type, sender, id
                + "05 72 65 6c 61 79 2a 01 ac 02", hex(d));  // role, epoch 42, state 1, status version 300 (0x2c | 0x80, 0x02)
    }

    @Test
    void echo_isHeaderThenTheEchoedHeartbeatsTag() {
        byte[] d = codec.datagram(new Envelope("uav1", 8, new Echo(Echo.tagOf(7))));
        assertEquals("53 4d 02 14 04 75 61 76 31 00 00 00 00 00 00 00 08 "
                + "00 00 00 08", hex(d));  // the tag of id 7: 7 mod (2^32 - 1) + 1
        byte[] top = codec.datagram(new Envelope("uav1", 9, new Echo(Echo.MAX_TAG)));
        assertEquals("ff ff ff ff", hex(top).substring(hex(top).length() - 11));  // unsigned
    }

    @Test
    void echoTags_areNeverZero_andDistinctForIdsCloserThanTheirModulus() {
        assertEquals(1, Echo.tagOf(Echo.MAX_TAG));
        assertEquals(Echo.MAX_TAG, Echo.tagOf(Echo.MAX_TAG - 1));
        long id = (1_700_000_000_000L << 16) + 12_345;   // ids start at the clock shifted left 16 bits
        java.util.Set<Long> tags = new java.util.HashSet<>();
        for (long i = 0; i < 10_000; i++) {
            long tag = Echo.tagOf(id + i * 65_537);
            org.junit.jupiter.api.Assertions.assertTrue(tag >= 1 && tag <= Echo.MAX_TAG);
            tags.add(tag);
        }
        assertEquals(10_000, tags.size());
        org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class, () -> new Echo(Echo.MAX_TAG + 1));
        org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class, () -> new Echo(-1));
    }

    @Test
    void aHeaderThatLeavesTheSenderToTheTransport_hasSenderLength0_andNoSender() {
        MessageEncoder encoder = new MessageEncoder().leaveSenderToTransport(java.util.Set.of(MessageType.HEARTBEAT));
        byte[] d = encoder.datagrams(new Envelope("uav1", 7, new Heartbeat("relay", 42, 1, 300))).get(0);
        assertEquals("53 4d 02 09 00 00 00 00 00 00 00 00 07 "   // magic, version, type, sender length 0, id
                + "05 72 65 6c 61 79 2a 01 ac 02", hex(d));
        byte[] echo = encoder.datagrams(new Envelope("uav1", 8, new Echo(Echo.tagOf(7)))).get(0);
        assertEquals("04 75 61 76 31", hex(echo).substring(12, 26), "a type not left to the transport names its sender");
    }

    @Test
    void aFragmentedMessageLeftToTheTransport_isReassembledUnderTheNamedSender() {
        MessageEncoder encoder = new MessageEncoder().leaveSenderToTransport(java.util.Set.of(MessageType.ROLE_EVENT));
        Envelope e = new Envelope("uav1", 3, Samples.bulk("r", 3_000));
        List<byte[]> d = encoder.datagrams(e);
        assertEquals(3, d.size());
        MessageDecoder decoder = new MessageDecoder(() -> 0L);
        assertInstanceOf(DecodeResult.FragmentPending.class, decoder.decode("uav1", d.get(0), 0, d.get(0).length));
        assertInstanceOf(DecodeResult.FragmentPending.class, decoder.decode("uav1", d.get(1), 0, d.get(1).length));
        assertEquals(e, ((DecodeResult.Decoded) decoder.decode("uav1", d.get(2), 0, d.get(2).length)).envelope());
        assertInstanceOf(DecodeResult.Rejected.class, decoder.decode(d.get(0)), "without a named sender");
    }

    @Test
    void roleEvent_valuesAreTagged() {
        byte[] d = codec.datagram(new Envelope("u", 1, new RoleEvent("r", "e", java.util.Arrays.asList(
                null, false, true, "hi", new java.math.BigDecimal("-1.5"), List.of()))));
        String payload = hex(d).substring(hex(d).indexOf(" 01 72"));  // after the header
        assertEquals(" 01 72 01 65 06 00 01 02 03 00 02 68 69 04 00 00 00 01 01 f1 05 00 00", payload);  // ..., origin ""
    }

    @Test
    void fragments_carryTypeIndexCountAndTotal() {
        Envelope e = new Envelope("u", 1, Samples.bulk("r", 2_007));
        List<byte[]> d = codec.encode(e);
        assertEquals(2, d.size());
        int total = 6 + 3 + 2_007;
        // header: magic, version, type 0xFF, sender "u", id 1; then 9 bytes of fragment header and a chunk of ceil(2016 / 2)
        assertEquals("53 4d 02 ff 01 75 00 00 00 00 00 00 00 01", hex(d.get(0)).substring(0, 41));
        // fragment header: type ROLE_EVENT, index 1, count 2, total 2016
        assertEquals("0b 00 01 00 02 00 00 07 e0", hex(d.get(1)).substring(42, 42 + 26));
        assertEquals(total, 0x7e0);
        assertEquals(14 + 9 + 1_008, d.get(0).length);
        assertEquals(14 + 9 + 1_008, d.get(1).length);
    }
}
