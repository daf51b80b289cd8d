package net.smc.core.wire;

import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import java.nio.ByteOrder;

/**
 * Reads fields big-endian from {@code array[start, end)}, checking every read and every length
 * against the bytes that remain before it moves or allocates anything, so that input can never make
 * a reader allocate more than the input itself could hold. Each method takes the name of its field;
 * a failed check becomes the format's exception through its {@link WireErrors}, at the offset of the
 * field from {@code start}.
 *
 * <p>A format adds its own fields (strings, counts, sets) on top, by subclassing or by static
 * helpers; the methods here are final. A reader can be {@linkplain #reset reset} and reused.
 *
 * @param <E> the format's exception
 */
public class ByteReader<E extends Exception> {
    private static final VarHandle I16 = MethodHandles.byteArrayViewVarHandle(short[].class, ByteOrder.BIG_ENDIAN);
    private static final VarHandle I32 = MethodHandles.byteArrayViewVarHandle(int[].class, ByteOrder.BIG_ENDIAN);
    private static final VarHandle I64 = MethodHandles.byteArrayViewVarHandle(long[].class, ByteOrder.BIG_ENDIAN);
    private static final byte[] EMPTY = new byte[0];

    private final WireErrors<E> errors;
    private byte[] buf = EMPTY;
    private int start;
    private int pos;
    private int end;

    /** A reader with nothing to read until {@link #reset}. */
    public ByteReader(WireErrors<E> errors) {
        this.errors = errors;
    }

    /** A reader of {@code buf[start, end)}. */
    public ByteReader(WireErrors<E> errors, byte[] buf, int start, int end) {
        this.errors = errors;
        reset(buf, start, end);
    }

    /** Reads {@code buf[start, end)} from its start; offsets in errors count from {@code start}. */
    public final void reset(byte[] buf, int start, int end) {
        if (start < 0 || start > end || end > buf.length) {
            throw new IndexOutOfBoundsException("range [" + start + ", " + end + ") of an array of " + buf.length);
        }
        this.buf = buf;
        this.start = start;
        this.pos = start;
        this.end = end;
    }

    /** The array read from (not a copy). */
    public final byte[] array() {
        return buf;
    }

    /** The index into {@link #array()} of the next byte. */
    public final int position() {
        return pos;
    }

    /** The offset of the next byte from where reading began. */
    public final int offset() {
        return pos - start;
    }

    public final int remaining() {
        return end - pos;
    }

    public final int u8(String field) throws E {
        require(1, field);
        return buf[pos++] & 0xFF;
    }

    public final int u16(String field) throws E {
        require(2, field);
        int v = (short) I16.get(buf, pos) & 0xFFFF;
        pos += 2;
        return v;
    }

    public final int i32(String field) throws E {
        require(4, field);
        int v = (int) I32.get(buf, pos);
        pos += 4;
        return v;
    }

    public final long i64(String field) throws E {
        require(8, field);
        long v = (long) I64.get(buf, pos);
        pos += 8;
        return v;
    }

    /**
     * A number written by {@code ByteWriter.varint}: 7-bit groups, least significant first, at most
     * 9 bytes and at most {@link Long#MAX_VALUE}, in its shortest form (a last byte of 0 after
     * another byte is refused, so that each number has exactly one encoding).
     */
    public final long varint(String field) throws E {
        int at = pos;
        long v = 0;
        for (int shift = 0; ; shift += 7) {
            if (shift > 56) {
                throw errors.error(WireProblem.MALFORMED, at - start, field, "is a varint longer than 9 bytes");
            }
            require(1, field);
            int b = buf[pos++] & 0xFF;
            if (shift == 56 && b > 0x7F) {
                throw errors.error(WireProblem.MALFORMED, at - start, field, "is a varint above " + Long.MAX_VALUE);
            }
            v |= (long) (b & 0x7F) << shift;
            if (b < 0x80) {
                if (b == 0 && shift > 0) {
                    throw errors.error(WireProblem.MALFORMED, at - start, field, "is a varint not in its shortest form");
                }
                return v;
            }
        }
    }

    /** A one-byte length or count in front of {@code field}; a shortage is reported as {@link WireErrors#truncatedLength}. */
    public final int length8(String field) throws E {
        requireLength(1, field);
        return buf[pos++] & 0xFF;
    }

    /** A two-byte length or count in front of {@code field}, as {@link #length8}. */
    public final int length16(String field) throws E {
        requireLength(2, field);
        int v = (short) I16.get(buf, pos) & 0xFFFF;
        pos += 2;
        return v;
    }

    /** A copy of the next {@code n} bytes. */
    public final byte[] bytes(int n, String field) throws E {
        require(n, field);
        byte[] out = new byte[n];
        System.arraycopy(buf, pos, out, 0, n);
        pos += n;
        return out;
    }

    /** Skips {@code n} bytes after checking they are there; returns their index in {@link #array()}. */
    public final int take(int n, String field) throws E {
        require(n, field);
        int at = pos;
        pos += n;
        return at;
    }

    /** The format's exception for {@code problem} in {@code field} at {@code offset} (from where reading began). */
    public final E error(WireProblem problem, int offset, String field, String rule) {
        return errors.error(problem, offset, field, rule);
    }

    /** Checks that {@code n} more bytes are there for {@code field}. */
    public final void require(int n, String field) throws E {
        if (end - pos < n) {
            throw errors.truncated(pos - start, field, n, end - pos);
        }
    }

    private void requireLength(int n, String field) throws E {
        if (end - pos < n) {
            throw errors.truncatedLength(pos - start, field, n, end - pos);
        }
    }
}
