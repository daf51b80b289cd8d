package net.smc.core.message;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.ByteBuffer;
import java.util.EnumSet;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;

class CodecRoundTripTest {
    private final Codec codec = new Codec();

    @Test
    void everyMessageType_hasAnOrdinarySample() {
        Set<MessageType> seen = EnumSet.noneOf(MessageType.class);
        Samples.ordinary().forEach(m -> seen.add(m.type()));
        assertEquals(EnumSet.allOf(MessageType.class), seen);
    }

    @Test
    void ordinaryMessages_roundTripForEverySender() {
        for (String sender : Samples.senders()) {
            long id = 1;
            for (Message m : Samples.ordinary()) {
                Envelope e = new Envelope(sender, id++, m);
                assertEquals(e, codec.roundTrip(e));
            }
        }
    }

    @Test
    void messagesAtTheirFieldLimits_roundTrip() {
        for (String sender : Samples.senders()) {
            for (Message m : Samples.boundaries()) {
                Envelope e = new Envelope(sender, Long.MIN_VALUE, m);
                assertEquals(e, codec.roundTrip(e));
            }
        }
    }

    @Test
    void numbers_keepTheirScale() {
        Envelope e = new Envelope("u", 1, new RoleEvent("r", "e",
                List.of(new java.math.BigDecimal("1.0"), new java.math.BigDecimal("1.00"))));
        List<Object> values = ((RoleEvent) codec.roundTrip(e).body()).values();
        assertEquals("1.0", values.get(0).toString());
        assertEquals("1.00", values.get(1).toString());
    }

    @Test
    void encodeIntoBuffer_writesTheSameBytesAsTheDatagramList() {
        ByteBuffer buf = ByteBuffer.allocate(2 * WireFormat.MAX_DATAGRAM);
        buf.position(5);
        Envelope e = new Envelope("uav1", 9, new Heartbeat("relay", 1, 2));
        int n = codec.encoder.encode(e, buf);
        assertEquals(5 + n, buf.position());
        byte[] written = new byte[n];
        buf.flip().position(5);
        buf.get(written);
        assertArrayEquals(codec.datagram(e), written);
    }

    @Test
    void decodeFromBuffers_leavesThemUnchanged() {
        byte[] d = codec.datagram(new Envelope("uav1", 9, new Heartbeat("relay", 1, 2)));
        ByteBuffer direct = ByteBuffer.allocateDirect(d.length + 3);
        direct.position(3);
        direct.put(d).flip().position(3);
        assertEquals(new Heartbeat("relay", 1, 2), Codec.decoded(codec.decoder.decode(direct)).body());
        assertEquals(3, direct.position());
        ByteBuffer readOnly = ByteBuffer.wrap(d).asReadOnlyBuffer();
        assertEquals(new Heartbeat("relay", 1, 2), Codec.decoded(codec.decoder.decode(readOnly)).body());
        assertEquals(0, readOnly.position());
    }

    @Test
    void theLargestAcks_fitsOneDatagram_withTheLongestSender() {
        Envelope e = new Envelope(Samples.ascii(64), 1, new Acks(Samples.maxAcks()));
        List<byte[]> datagrams = codec.encode(e);
        assertEquals(1, datagrams.size());
        // header 13 + sender 64, count 1, 128 ids of 8 bytes
        assertEquals(13 + 64 + 1 + 8 * WireFormat.MAX_ACKS, datagrams.get(0).length);
        assertTrue(datagrams.get(0).length <= WireFormat.MAX_DATAGRAM);
        assertEquals(e, codec.roundTrip(e));
    }

    @Test
    void aDatagramOfExactly1400Bytes_isNotFragmented_and1401Are() {
        String sender = Samples.ascii(64);
        // RoleEvent payload: role 1+1, event 1+1, one string value 1+1+2+n, origin 1; header 13+64.
        int text = WireFormat.MAX_DATAGRAM - (13 + 64) - (6 + 3);
        Envelope fits = new Envelope(sender, 1, Samples.bulk("r", text));
        assertEquals(WireFormat.MAX_DATAGRAM, codec.datagram(fits).length);
        assertEquals(fits, codec.roundTrip(fits));
        Envelope over = new Envelope(sender, 2, Samples.bulk("r", text + 1));
        List<byte[]> datagrams = codec.encode(over);
        assertEquals(2, datagrams.size());
        datagrams.forEach(d -> assertTrue(d.length <= WireFormat.MAX_DATAGRAM));
        assertEquals(over, codec.roundTrip(over));
    }

    @Test
    void aMessageOf20KB_isFragmentedAndReassembled() {
        Envelope e = new Envelope("uav1", 77, Samples.bulk("relay", 20_000));
        List<byte[]> datagrams = codec.encode(e);
        assertEquals(15, datagrams.size());  // 20,025 payload bytes, 1,374 per fragment
        datagrams.forEach(d -> assertTrue(d.length <= WireFormat.MAX_DATAGRAM));
        assertEquals(e, codec.roundTrip(e));
        assertEquals(0, codec.decoder.reassembliesInProgress());
        assertEquals(0, codec.decoder.bufferedBytes());
    }

    @Test
    void largeCapabilityDescription_isFragmentedAndReassembled() {
        Envelope e = new Envelope("uav2", 3, new CapabilityReply(2, Samples.description(20, 12)));
        List<byte[]> datagrams = codec.encode(e);
        assertTrue(datagrams.size() > 10, datagrams.size() + " datagrams");
        assertEquals(e, codec.roundTrip(e));
    }

    @Test
    void largestPayload_roundTrips_andAnOversizeDescriptionIsRefusedByTheEncoder() {
        // PolicyReply payload: 8 + (1 + 255) + 4 + (2 + n) = 65,535 at n = 65,265: over the text limit,
        // so fill with a multi-byte text at the text limit and a long URI instead.
        String uri = Samples.ascii(255);
        Envelope largest = new Envelope(Samples.ascii(64), 4, new PolicyReply(1, uri, 1,
                Samples.mixed(WireFormat.MAX_POLICY_TEXT)));
        assertEquals(largest, codec.roundTrip(largest));
        assertTrue(codec.encode(largest).size() <= WireFormat.MAX_FRAGMENTS);

        Envelope tooLarge = new Envelope("u", 5, new CapabilityReply(1, Samples.description(63, 20)));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> codec.encode(tooLarge));
        assertEquals("capability description is longer than 64511 bytes encoded, the limit", e.getMessage());
    }

    @Test
    void encodeIntoBuffer_refusesAMessageThatNeedsFragments() {
        Envelope e = new Envelope("uav1", 8, Samples.bulk("r", 5_000));
        ByteBuffer buf = ByteBuffer.allocate(WireFormat.MAX_DATAGRAM);
        IllegalArgumentException ex = assertThrows(IllegalArgumentException.class, () -> codec.encoder.encode(e, buf));
        assertTrue(ex.getMessage().startsWith("ROLE_EVENT from 'uav1' (id 8): its payload of 5012 bytes needs"
                + " fragments"), ex.getMessage());
        assertEquals(0, buf.position());
    }

    @Test
    void encodeIntoBuffer_refusesABufferTooSmall() {
        Envelope e = new Envelope("uav1", 8, new Heartbeat("relay", 1, 1));
        ByteBuffer buf = ByteBuffer.allocate(10);
        IllegalArgumentException ex = assertThrows(IllegalArgumentException.class, () -> codec.encoder.encode(e, buf));
        assertEquals("HEARTBEAT from 'uav1' (id 8): the buffer has 10 bytes left; the datagram needs 26",
                ex.getMessage());
    }

    @Test
    void counters_countMessagesDatagramsAndDecodes() {
        codec.roundTrip(new Envelope("u", 1, new Ack(1)));
        codec.roundTrip(new Envelope("u", 2, Samples.bulk("r", 3_000)));
        assertEquals(2, codec.encoder.messages());
        assertEquals(4, codec.encoder.datagrams());
        assertEquals(2, codec.decoder.decoded());
        assertEquals(2, codec.decoder.fragmentsPending());
        assertEquals(0, codec.decoder.rejected());
    }

    @Test
    void rolesAcrossVehicles_fieldsSurviveTheWire() {
        Envelope e = new Envelope("d1", 7, new RoleEvent("hdetector", "hazardDetected", List.of("gas"), "d2"));
        assertEquals("d2", ((RoleEvent) codec.roundTrip(e).body()).origin());
        Invocation i = new Invocation("aggregator", "report:x:y:", List.of("gas"), "hdetector", 42, "d2", "10.0.0.7:4001");
        Invocation back = (Invocation) codec.roundTrip(new Envelope("s1", 8, i)).body();
        assertEquals(i, back);
        assertEquals(42, back.call());
        assertEquals("hdetector", back.caller());
        assertEquals("10.0.0.7:4001", back.reply());
        assertEquals("d1", new Invocation("r", "release", List.of()).originOr("d1"));
    }

    @Test
    void anInvocationWithANegativeCall_isRefused() {
        assertThrows(IllegalArgumentException.class, () -> new Invocation("r", "o", List.of(), "c", -1, "", ""));
    }

    @Test
    void aCellRequest_survivesTheWire() {
        CellRequest r = new CellRequest(CellRequest.Kind.EVENT, "a1", "role/aggregator", "", "hazardDetected",
                List.of(List.of("#map", "kind", "gas")), "hdetector", 3, "d2", "10.0.0.7:4001");
        assertEquals(r, codec.roundTrip(new Envelope("d1", 9, r)).body());
        CellRequest text = new CellRequest(CellRequest.Kind.EVALUATE, "a1", "", "test:", "", List.of("1 + 2."),
                "hdetector", 4, "", "");
        assertEquals(text, codec.roundTrip(new Envelope("d1", 10, text)).body());
    }

    @Test
    void aCellRequestToEvaluateAnythingButText_isRefused() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new CellRequest(
                CellRequest.Kind.EVALUATE, "a1", "", "execute:", "", List.of(java.math.BigDecimal.ONE), "r", 1, "", ""));
        assertTrue(e.getMessage().contains("carries its text as a string"), e.getMessage());
    }
}
