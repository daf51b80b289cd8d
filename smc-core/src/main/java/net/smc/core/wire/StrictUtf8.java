package net.smc.core.wire;

import java.nio.charset.StandardCharsets;

/**
 * UTF-8 without the JDK's allocating paths: {@link ByteWriter} writes strings straight into its
 * buffer and readers check bytes before they build a string, strictly, so that every accepted string
 * re-encodes to the very bytes it came from.
 */
public final class StrictUtf8 {
    private StrictUtf8() {
    }

    /** The UTF-8 length of {@code s}, or -1 if it holds an unpaired surrogate (which has no UTF-8 form). */
    public static int length(String s) {
        int n = 0;
        int len = s.length();
        for (int i = 0; i < len; i++) {
            char c = s.charAt(i);
            if (c < 0x80) {
                n += 1;
            } else if (c < 0x800) {
                n += 2;
            } else if (Character.isSurrogate(c)) {
                if (Character.isHighSurrogate(c) && i + 1 < len && Character.isLowSurrogate(s.charAt(i + 1))) {
                    n += 4;
                    i++;
                } else {
                    return -1;
                }
            } else {
                n += 3;
            }
        }
        return n;
    }

    /** Writes {@code s} (well formed, as {@link #length} checked) at {@code pos}; returns the position after it. */
    public static int encode(String s, byte[] dst, int pos) {
        int len = s.length();
        for (int i = 0; i < len; i++) {
            char c = s.charAt(i);
            if (c < 0x80) {
                dst[pos++] = (byte) c;
            } else if (c < 0x800) {
                dst[pos++] = (byte) (0xC0 | c >> 6);
                dst[pos++] = (byte) (0x80 | c & 0x3F);
            } else if (Character.isHighSurrogate(c)) {
                int cp = Character.toCodePoint(c, s.charAt(++i));
                dst[pos++] = (byte) (0xF0 | cp >> 18);
                dst[pos++] = (byte) (0x80 | cp >> 12 & 0x3F);
                dst[pos++] = (byte) (0x80 | cp >> 6 & 0x3F);
                dst[pos++] = (byte) (0x80 | cp & 0x3F);
            } else {
                dst[pos++] = (byte) (0xE0 | c >> 12);
                dst[pos++] = (byte) (0x80 | c >> 6 & 0x3F);
                dst[pos++] = (byte) (0x80 | c & 0x3F);
            }
        }
        return pos;
    }

    /**
     * Whether {@code b[off, off+len)} is well-formed UTF-8 (RFC 3629): no overlong forms, no
     * surrogates, nothing above U+10FFFF, no truncated sequence.
     */
    public static boolean isWellFormed(byte[] b, int off, int len) {
        int i = off;
        int end = off + len;
        while (i < end) {
            int c = b[i] & 0xFF;
            if (c < 0x80) {
                i++;
                continue;
            }
            int need;
            int min;
            if (c >= 0xC2 && c <= 0xDF) {
                need = 1;
                min = 0x80;
            } else if (c >= 0xE0 && c <= 0xEF) {
                need = 2;
                min = 0x800;
            } else if (c >= 0xF0 && c <= 0xF4) {
                need = 3;
                min = 0x10000;
            } else {
                return false;
            }
            if (end - i <= need) {
                return false;
            }
            int cp = c & (0x3F >> need);
            for (int k = 1; k <= need; k++) {
                int cc = b[i + k] & 0xFF;
                if ((cc & 0xC0) != 0x80) {
                    return false;
                }
                cp = cp << 6 | cc & 0x3F;
            }
            if (cp < min || cp > 0x10FFFF || cp >= 0xD800 && cp <= 0xDFFF) {
                return false;
            }
            i += need + 1;
        }
        return true;
    }

    /** Decodes bytes that {@link #isWellFormed} accepted. */
    public static String decode(byte[] b, int off, int len) {
        return new String(b, off, len, StandardCharsets.UTF_8);
    }
}
