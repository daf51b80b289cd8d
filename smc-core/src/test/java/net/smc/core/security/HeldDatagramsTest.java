package net.smc.core.security;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;

import net.smc.core.transport.Address;

class HeldDatagramsTest {

    @Test
    void nothingIsHeld_untilAReceiverIsSet_andThenOnlyWhatItsTestAccepts() {
        HeldDatagrams held = new HeldDatagrams();
        byte[] data = {7, 1, 2};
        assertFalse(held.accepts(data, 0, 3), "no receiver yet");
        held.set((d, offset, length) -> d[offset] == 7, (from, payload) -> { });
        assertTrue(held.accepts(data, 0, 3));
        assertFalse(held.accepts(data, 1, 2));
    }

    @Test
    void theNewestPerSourceIsHeld_andTakenOnce() {
        HeldDatagrams held = new HeldDatagrams();
        List<byte[]> read = new ArrayList<>();
        held.set((d, offset, length) -> true, (from, payload) -> read.add(payload));
        Address a = Address.loopback(4000);
        held.hold(a, new byte[] {1}, new byte[] {10});
        held.hold(a, new byte[] {2}, new byte[] {20});
        assertEquals(2, read.size(), "the receiver reads every payload held");
        assertEquals(2, held.count());
        assertArrayEquals(new byte[] {2}, held.take(a), "the newer replaces the older");
        assertNull(held.take(a), "taken once");
    }

    @Test
    void aFloodFromManySources_pushesOutTheOldest_andNoMoreThanTheBoundIsHeld() {
        HeldDatagrams held = new HeldDatagrams();
        held.set((d, offset, length) -> true, (from, payload) -> { });
        int sources = HeldDatagrams.MAX_HELD + 10;
        for (int i = 0; i < sources; i++) {
            held.hold(Address.loopback(5000 + i), new byte[] {(byte) i}, new byte[0]);
        }
        int kept = 0;
        for (int i = 0; i < sources; i++) {
            byte[] d = held.take(Address.loopback(5000 + i));
            if (i < 10) {
                assertNull(d, "the oldest sources went first: " + i);
            } else {
                assertNotNull(d, "a newer source is kept: " + i);
                kept++;
            }
        }
        assertEquals(HeldDatagrams.MAX_HELD, kept);
    }
}
