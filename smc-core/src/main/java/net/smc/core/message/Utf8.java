package net.smc.core.message;

import net.smc.core.wire.StrictUtf8;

/** The strict UTF-8 of the datagram codec: {@link StrictUtf8}, which the shared reader and writer use. */
final class Utf8 {
    private Utf8() {
    }

    /** The UTF-8 length of {@code s}, or -1 if it holds an unpaired surrogate. */
    static int length(String s) {
        return StrictUtf8.length(s);
    }

    /** Writes {@code s} (well formed) at {@code pos}; returns the position after it. */
    static int encode(String s, byte[] dst, int pos) {
        return StrictUtf8.encode(s, dst, pos);
    }

    static boolean isWellFormed(byte[] b, int off, int len) {
        return StrictUtf8.isWellFormed(b, off, len);
    }

    static String decode(byte[] b, int off, int len) {
        return StrictUtf8.decode(b, off, len);
    }
}
