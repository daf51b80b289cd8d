package net.smc.core.message;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.nio.charset.StandardCharsets;

import org.junit.jupiter.api.Test;

/** The names decoders share: the same bytes give the same string to every decoder, never a wrong one. */
class StringCacheTest {
    private static byte[] bytes(String s) {
        return s.getBytes(StandardCharsets.UTF_8);
    }

    @Test
    void everyDecoderGetsTheSameStringForTheSameName() {
        byte[] datagram = bytes("xx-b3l2n7-yy");
        String first = new StringCache().get(datagram, 3, 6);
        assertEquals("b3l2n7", first);
        assertSame(first, new StringCache().get(bytes("b3l2n7"), 0, 6));
    }

    @Test
    void manyNamesEachDecodeToThemselves() {
        StringCache cache = new StringCache();
        for (int round = 0; round < 2; round++) {
            for (int i = 0; i < 20_000; i++) {
                String name = "v" + i + "\u00e9";
                assertEquals(name, cache.get(bytes(name), 0, bytes(name).length));
            }
        }
    }

    @Test
    void malformedBytesAreRefusedWhateverIsCached() {
        StringCache cache = new StringCache();
        byte[] good = bytes("ab\u00e9");
        assertEquals("ab\u00e9", cache.get(good, 0, good.length));
        byte[] cut = {'a', 'b', (byte) 0xC3};
        assertNull(cache.get(cut, 0, cut.length));
        byte[] overlong = {'a', 'b', (byte) 0xC0, (byte) 0xAF};
        assertNull(cache.get(overlong, 0, overlong.length));
        byte[] longName = new byte[100];
        java.util.Arrays.fill(longName, (byte) 'n');
        assertEquals("n".repeat(100), cache.get(longName, 0, 100));
        longName[99] = (byte) 0xFF;
        assertNull(cache.get(longName, 0, 100));
    }
}
