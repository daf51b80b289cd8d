package net.smc.core.message;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;

import org.junit.jupiter.api.Test;

class SharedDecodesTest {
    private final SharedDecodes table = new SharedDecodes();
    private final MessageEncoder encoder = new MessageEncoder();

    private MessageDecoder decoder() {
        return new MessageDecoder(() -> 0L).share(table);
    }

    private byte[] datagram(String sender, long id, Message body) {
        return encoder.datagrams(new Envelope(sender, id, body)).get(0);
    }

    @Test
    void aBroadcastDiscoveryIsDecodedOnce_andEveryDecoderGetsTheSameEnvelope() {
        byte[] d = datagram("b0l1n2", 77, new Discovery("m", "b0l1", 1, 3));
        MessageDecoder a = decoder();
        MessageDecoder b = decoder();
        Envelope first = Codec.decoded(a.decode(d.clone()));
        Envelope second = Codec.decoded(b.decode(d.clone()));
        assertSame(first, second);
        assertEquals(new Envelope("b0l1n2", 77, new Discovery("m", "b0l1", 1, 3)), second);
        assertEquals(1, a.decoded());
        assertEquals(1, b.decoded());
        assertEquals(1, table.hits());
        assertEquals(1, table.misses());
    }

    @Test
    void differentBytesAreDecodedOnTheirOwn() {
        MessageDecoder a = decoder();
        Envelope one = Codec.decoded(a.decode(datagram("cdr", 1, new Discovery("m", "cdr", 0, 3))));
        Envelope other = Codec.decoded(a.decode(datagram("cdr", 2, new Discovery("m", "cdr", 0, 3))));
        assertEquals(1, one.id());
        assertEquals(2, other.id());
        assertEquals(0, table.hits());
    }

    @Test
    void twoSendersWithTheSameIdAreToldApart() {
        MessageDecoder a = decoder();
        MessageDecoder b = decoder();
        byte[] fromX = datagram("b0l1n2", 40, new Discovery("m", "b0l1", 1, 3));
        byte[] fromY = datagram("b0l1n3", 40, new Discovery("m", "b0l1", 1, 3));
        for (int i = 0; i < 3; i++) {
            assertEquals("b0l1n2", Codec.decoded(a.decode(fromX)).sender());
            assertEquals("b0l1n3", Codec.decoded(b.decode(fromY)).sender());
        }
    }

    @Test
    void aDiscoveryCutShortInItsHeaderIsRejected() {
        byte[] d = datagram("cdr", 9, new Discovery("m", "cdr", 0, 3));
        for (int cut = 4; cut < 20; cut++) {
            Codec.rejected(decoder().decode(java.util.Arrays.copyOf(d, cut)));
        }
        assertEquals(0, table.hits());
    }

    @Test
    void unicastTypesAreNotKept() {
        byte[] d = datagram("r1", 5, new Heartbeat("surveyor", 2, 1));
        Envelope first = Codec.decoded(decoder().decode(d));
        Envelope second = Codec.decoded(decoder().decode(d));
        assertEquals(first, second);
        assertNotSame(first, second);
        assertEquals(0, table.hits() + table.misses());
    }

    @Test
    void aDiscoveryThatLeavesItsSenderToTheTransport_isNotShared_forItsBytesDoNotNameIt() {
        byte[] d = new MessageEncoder().leaveSenderToTransport(java.util.Set.of(MessageType.DISCOVERY))
                .datagrams(new Envelope("cdr", 9, new Discovery("m", "cdr", 0, 3))).get(0);
        assertEquals("cdr", Codec.decoded(decoder().decode("cdr", d, 0, d.length)).sender());
        assertEquals("uav-2", Codec.decoded(decoder().decode("uav-2", d, 0, d.length)).sender());
        assertEquals(0, table.hits() + table.misses());
    }

    @Test
    void aRejectedDiscoveryIsNotKept_soEachDecoderRejectsAndCountsIt() {
        byte[] d = datagram("cdr", 9, new Discovery("m", "cdr", 0, 3));
        byte[] bad = java.util.Arrays.copyOf(d, d.length - 1); // cut short: its last field is incomplete
        MessageDecoder a = decoder();
        MessageDecoder b = decoder();
        Codec.rejected(a.decode(bad));
        Codec.rejected(b.decode(bad));
        assertEquals(1, a.rejected());
        assertEquals(1, b.rejected());
        assertEquals(0, table.hits());
        // the good datagram is still decoded, and then shared
        assertSame(Codec.decoded(a.decode(d)), Codec.decoded(b.decode(d)));
    }
}
