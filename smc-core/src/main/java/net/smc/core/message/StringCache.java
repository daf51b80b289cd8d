package net.smc.core.message;

import java.util.Arrays;

/**
 * Remembers the strings of recently decoded names, so that the sender and role of the thousandth
 * heartbeat from the same peer cost a hash and a byte comparison instead of a new string. A small
 * direct-mapped table: a collision simply replaces the older entry, so its size never grows and a
 * peer sending ever-new names only costs itself the cache hits.
 */
final class StringCache {
    private static final int SLOTS = 256;
    /** Longer strings are not cached: names are at most 64 bytes. */
    static final int MAX_LENGTH = 64;

    private final byte[][] keys = new byte[SLOTS][];
    private final String[] values = new String[SLOTS];

    /** The string of {@code b[off, off+len)}, or null if those bytes are not well-formed UTF-8. */
    String get(byte[] b, int off, int len) {
        if (len > MAX_LENGTH) {
            return Utf8.isWellFormed(b, off, len) ? Utf8.decode(b, off, len) : null;
        }
        int h = len;
        for (int i = off, end = off + len; i < end; i++) {
            h = 31 * h + b[i];
        }
        int slot = (h ^ h >>> 16) & SLOTS - 1;
        byte[] key = keys[slot];
        if (key != null && Arrays.equals(key, 0, key.length, b, off, off + len)) {
            return values[slot];
        }
        if (!Utf8.isWellFormed(b, off, len)) {
            return null;
        }
        String s = Utf8.decode(b, off, len);
        keys[slot] = Arrays.copyOfRange(b, off, off + len);
        values[slot] = s;
        return s;
    }
}
