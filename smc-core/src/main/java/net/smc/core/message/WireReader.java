package net.smc.core.message;

import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import java.nio.ByteOrder;

/**
 * Reads fields big-endian from a byte range, checking every length against the bytes that remain
 * (and against the field's limit) before it allocates anything, so a datagram can never make the
 * decoder allocate more than the datagram itself could hold. Each method names its field in the
 * {@link DecodeException} it throws. Reused from datagram to datagram.
 */
final class WireReader {
    private static final VarHandle I16 = MethodHandles.byteArrayViewVarHandle(short[].class, ByteOrder.BIG_ENDIAN);
    private static final VarHandle I32 = MethodHandles.byteArrayViewVarHandle(int[].class, ByteOrder.BIG_ENDIAN);
    private static final VarHandle I64 = MethodHandles.byteArrayViewVarHandle(long[].class, ByteOrder.BIG_ENDIAN);

    private final StringCache names = new StringCache();
    private byte[] buf;
    private int pos;
    private int limit;

    void reset(byte[] buf, int offset, int limit) {
        this.buf = buf;
        this.pos = offset;
        this.limit = limit;
    }

    byte[] array() {
        return buf;
    }

    int position() {
        return pos;
    }

    int remaining() {
        return limit - pos;
    }

    int u8(String field) throws DecodeException {
        require(1, field);
        return buf[pos++] & 0xFF;
    }

    int u16(String field) throws DecodeException {
        require(2, field);
        int v = (short) I16.get(buf, pos) & 0xFFFF;
        pos += 2;
        return v;
    }

    int i32(String field) throws DecodeException {
        require(4, field);
        int v = (int) I32.get(buf, pos);
        pos += 4;
        return v;
    }

    long i64(String field) throws DecodeException {
        require(8, field);
        long v = (long) I64.get(buf, pos);
        pos += 8;
        return v;
    }

    boolean bool(String field) throws DecodeException {
        int b = u8(field);
        if (b > 1) {
            throw new DecodeException(RejectReason.MALFORMED, field + " is " + b + "; a boolean is 0 or 1");
        }
        return b == 1;
    }

    /** A name: one length byte, at most {@link WireFormat#MAX_NAME} bytes; cached. */
    String name(String field) throws DecodeException {
        return string8(field, WireFormat.MAX_NAME);
    }

    /** A string with a one-byte length, at most {@code max} bytes. */
    String string8(String field, int max) throws DecodeException {
        requireLength(1, field);
        return string(field, buf[pos++] & 0xFF, max);
    }

    /** A string with a two-byte length, at most {@code max} bytes. */
    String string16(String field, int max) throws DecodeException {
        requireLength(2, field);
        int len = (short) I16.get(buf, pos) & 0xFFFF;
        pos += 2;
        return string(field, len, max);
    }

    private String string(String field, int len, int max) throws DecodeException {
        if (len > max) {
            throw new DecodeException(RejectReason.OVERSIZED, field + " is " + len + " bytes; at most " + max
                    + " are allowed");
        }
        require(len, field);
        String s = names.get(buf, pos, len);
        if (s == null) {
            throw new DecodeException(RejectReason.MALFORMED, field + " is not well-formed UTF-8");
        }
        pos += len;
        return s;
    }

    /**
     * A one-byte element count, at most {@code max}, and no more than the remaining bytes could
     * hold at {@code minBytes} each: checked before the caller sizes a list by it.
     */
    int count(String field, int max, int minBytes) throws DecodeException {
        requireLength(1, field);
        return checkCount(field, buf[pos++] & 0xFF, max, minBytes);
    }

    /** A two-byte element count, checked as {@link #count} checks a one-byte one. */
    int count16(String field, int max, int minBytes) throws DecodeException {
        return checkCount(field, u16(field), max, minBytes);
    }

    private int checkCount(String field, int n, int max, int minBytes) throws DecodeException {
        if (n > max) {
            throw new DecodeException(RejectReason.OVERSIZED, field + " has " + n + " elements; at most " + max
                    + " are allowed");
        }
        if ((long) n * minBytes > remaining()) {
            throw new DecodeException(RejectReason.TRUNCATED, field + " has " + n + " elements but only "
                    + remaining() + " bytes remain");
        }
        return n;
    }

    /** Skips {@code n} bytes after checking they are there; returns their offset in {@link #array()}. */
    int take(int n, String field) throws DecodeException {
        require(n, field);
        int at = pos;
        pos += n;
        return at;
    }

    /** Checks that every byte was read: a canonical payload has nothing after its last field. */
    void end() throws DecodeException {
        if (pos != limit) {
            throw new DecodeException(RejectReason.MALFORMED, (limit - pos) + " bytes follow the last field");
        }
    }

    /** Like {@link #require}, for the length or count in front of {@code field}. */
    private void requireLength(int n, String field) throws DecodeException {
        if (limit - pos < n) {
            throw new DecodeException(RejectReason.TRUNCATED, "the length of " + field + " needs " + n
                    + " bytes but " + (limit - pos) + " remain");
        }
    }

    private void require(int n, String field) throws DecodeException {
        if (limit - pos < n) {
            throw new DecodeException(RejectReason.TRUNCATED, field + " needs " + n + " bytes but "
                    + (limit - pos) + " remain");
        }
    }
}
