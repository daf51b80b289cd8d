package net.smc.core.message;

import java.util.Arrays;

/**
 * Remembers the strings of recently decoded names, so that the sender and role of the thousandth
 * heartbeat from the same peer cost a hash and a byte comparison instead of a new string and a
 * UTF-8 check. One table serves every decoder of the JVM: a simulation of a thousand cells decodes
 * the same few thousand names over and over, and one table of them stays in the processor's cache
 * where a table per cell (touched a few times a second each) would not. A direct-mapped table of
 * immutable entries: a collision simply replaces the older entry, so its size never grows, and a
 * peer sending ever-new names costs only cache hits (never a wrong string: an entry is used only
 * when its bytes are those being decoded). Safe without locks: an entry is written whole, with final
 * fields, and a reader sees either some complete entry or none.
 */
final class StringCache {
    private static final int BITS = 12;
    /** Longer strings are not cached: names are at most 64 bytes. */
    static final int MAX_LENGTH = 64;

    /** The bytes of a well-formed name and its string. */
    private record Entry(byte[] key, String value) {
    }

    private static final Entry[] TABLE = new Entry[1 << BITS];

    /** The string of {@code b[off, off+len)}, or null if those bytes are not well-formed UTF-8. */
    String get(byte[] b, int off, int len) {
        if (len > MAX_LENGTH) {
            return Utf8.isWellFormed(b, off, len) ? Utf8.decode(b, off, len) : null;
        }
        int h = len;
        for (int i = off, end = off + len; i < end; i++) {
            h = 31 * h + b[i];
        }
        int slot = (h * 0x9E3779B9) >>> (32 - BITS);
        Entry e = TABLE[slot];
        if (e != null && Arrays.equals(e.key, 0, e.key.length, b, off, off + len)) {
            return e.value;
        }
        if (!Utf8.isWellFormed(b, off, len)) {
            return null;
        }
        String s = Utf8.decode(b, off, len);
        TABLE[slot] = new Entry(Arrays.copyOfRange(b, off, off + len), s);
        return s;
    }
}
