package net.smc.core.security;

/**
 * Reads the primitives of the credential and envelope forms from bytes that may hold anything.
 * Every length is checked against the bytes left before anything is copied, and every error names
 * the field and the byte offset.
 */
final class WireIn {
    private final byte[] data;
    private final int start;
    private final int end;
    private final String what;
    private int pos;

    /** Reads {@code data[start, end)}; {@code what} names the form in errors ("credential", "signed datagram"). */
    WireIn(byte[] data, int start, int end, String what) {
        this.data = data;
        this.start = start;
        this.end = end;
        this.what = what;
        this.pos = start;
    }

    int u8(String field) throws Malformed {
        need(1, field);
        return data[pos++] & 0xff;
    }

    long i64(String field) throws Malformed {
        need(8, field);
        long v = 0;
        for (int i = 0; i < 8; i++) {
            v = (v << 8) | (data[pos++] & 0xff);
        }
        return v;
    }

    int i32(String field) throws Malformed {
        need(4, field);
        int v = 0;
        for (int i = 0; i < 4; i++) {
            v = (v << 8) | (data[pos++] & 0xff);
        }
        return v;
    }

    byte[] bytes(int n, String field) throws Malformed {
        need(n, field);
        byte[] out = new byte[n];
        System.arraycopy(data, pos, out, 0, n);
        pos += n;
        return out;
    }

    /** A name: one length byte (1 to {@link WireNames#MAX_BYTES}), then UTF-8. */
    String name(String field) throws Malformed {
        int at = offset();
        int length = u8(field + " length");
        if (length == 0 || length > WireNames.MAX_BYTES) {
            throw error(at, field, "length " + length + "; it must be 1 to " + WireNames.MAX_BYTES);
        }
        need(length, field);
        String s = WireNames.decode(data, pos, length);
        if (s == null) {
            throw error(at, field, "not valid UTF-8");
        }
        pos += length;
        return s;
    }

    /** Skips {@code n} bytes. */
    void skip(int n, String field) throws Malformed {
        need(n, field);
        pos += n;
    }

    /** The absolute index into the array of the next byte. */
    int position() {
        return pos;
    }

    int remaining() {
        return end - pos;
    }

    /** Offset of the next byte from where reading began. */
    int offset() {
        return pos - start;
    }

    Malformed error(int at, String field, String rule) {
        return new Malformed(what + ": " + field + " at byte " + at + ": " + rule);
    }

    private void need(int n, String field) throws Malformed {
        if (end - pos < n) {
            throw error(offset(), field, "truncated: needs " + n + " bytes, " + (end - pos) + " left");
        }
    }
}
