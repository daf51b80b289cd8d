package net.smc.core.wire;

import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import java.nio.ByteOrder;
import java.util.Arrays;
import java.util.function.Supplier;

/**
 * Writes fields big-endian into an array, from a start up to a limit. The array is either the
 * caller's, of a fixed size ({@link #ByteWriter(byte[], Supplier)}), or the writer's own, grown as
 * needed up to the limit ({@link #growing}). Going past the limit throws what the format's
 * {@code overflow} supplies: a format decides whether that is the caller's mistake or a signal
 * (the datagram codec uses one preallocated, traceless exception).
 */
public final class ByteWriter {
    private static final VarHandle I16 = MethodHandles.byteArrayViewVarHandle(short[].class, ByteOrder.BIG_ENDIAN);
    private static final VarHandle I32 = MethodHandles.byteArrayViewVarHandle(int[].class, ByteOrder.BIG_ENDIAN);
    private static final VarHandle I64 = MethodHandles.byteArrayViewVarHandle(long[].class, ByteOrder.BIG_ENDIAN);

    private final Supplier<? extends RuntimeException> overflow;
    private byte[] buf;
    private int start;
    private int pos;
    private int limit;
    /** {@code min(limit, buf.length)}: one comparison on the path that fits. */
    private int room;

    /** Writes into {@code buf}, all of it, until {@link #reset}. */
    public ByteWriter(byte[] buf, Supplier<? extends RuntimeException> overflow) {
        this.buf = buf;
        this.overflow = overflow;
        reset(0, buf.length);
    }

    /** A writer into an array of its own that grows up to {@code limit} bytes. */
    public static ByteWriter growing(int initialCapacity, int limit, Supplier<? extends RuntimeException> overflow) {
        ByteWriter w = new ByteWriter(new byte[Math.min(initialCapacity, limit)], overflow);
        w.reset(0, limit);
        return w;
    }

    /** Writes from {@code start}, up to {@code limit}. */
    public void reset(int start, int limit) {
        this.start = start;
        this.pos = start;
        this.limit = limit;
        this.room = Math.min(limit, buf.length);
    }

    /** The array written (not a copy): it may change as a growing writer grows. */
    public byte[] array() {
        return buf;
    }

    public int position() {
        return pos;
    }

    /** A copy of what was written since the start. */
    public byte[] toByteArray() {
        return Arrays.copyOfRange(buf, start, pos);
    }

    public void u8(int v) {
        ensure(1);
        buf[pos++] = (byte) v;
    }

    public void u16(int v) {
        ensure(2);
        I16.set(buf, pos, (short) v);
        pos += 2;
    }

    public void i32(int v) {
        ensure(4);
        I32.set(buf, pos, v);
        pos += 4;
    }

    public void i64(long v) {
        ensure(8);
        I64.set(buf, pos, v);
        pos += 8;
    }

    /**
     * A non-negative number in 7-bit groups, least significant first, the high bit of each byte
     * set when another follows (unsigned LEB128), in its shortest form: 1 byte up to 127, 2 up to
     * 16,383, at most 9 for a long. For fields that are usually small.
     *
     * @throws IllegalArgumentException if {@code v} is negative
     */
    public void varint(long v) {
        if (v < 0) {
            throw new IllegalArgumentException("a varint is 0 or more; got " + v);
        }
        ensure(9);
        while (v >= 0x80) {
            buf[pos++] = (byte) (v | 0x80);
            v >>>= 7;
        }
        buf[pos++] = (byte) v;
    }

    public void bool(boolean v) {
        u8(v ? 1 : 0);
    }

    /** A string with a one-byte length: the caller guarantees it is well formed and at most 255 bytes. */
    public void string8(String s) {
        int len = StrictUtf8.length(s);
        ensure(1 + len);
        buf[pos++] = (byte) len;
        pos = StrictUtf8.encode(s, buf, pos);
    }

    /** A string with a two-byte length: well formed and at most 65535 bytes. */
    public void string16(String s) {
        string16(s, StrictUtf8.length(s));
    }

    /** As {@link #string16(String)}, when the caller already has the {@link StrictUtf8#length}. */
    public void string16(String s, int utf8Length) {
        ensure(2 + utf8Length);
        I16.set(buf, pos, (short) utf8Length);
        pos = StrictUtf8.encode(s, buf, pos + 2);
    }

    public void bytes(byte[] src) {
        bytes(src, 0, src.length);
    }

    /** The {@code length} bytes of {@code src} from {@code offset}. */
    public void bytes(byte[] src, int offset, int length) {
        ensure(length);
        System.arraycopy(src, offset, buf, pos, length);
        pos += length;
    }

    private void ensure(int n) {
        if (room - pos < n) {
            grow(n);
        }
    }

    private void grow(int n) {
        if (limit - pos < n) {
            throw overflow.get();
        }
        int size = (int) Math.min(limit, Math.max((long) pos + n, 2L * buf.length));
        buf = Arrays.copyOf(buf, size);
        room = Math.min(limit, buf.length);
    }

    /** Writes a big-endian short into {@code dst} at {@code at}: for headers written after their payload. */
    public static void putU16(byte[] dst, int at, int v) {
        I16.set(dst, at, (short) v);
    }

    public static void putI32(byte[] dst, int at, int v) {
        I32.set(dst, at, v);
    }

    public static void putI64(byte[] dst, int at, long v) {
        I64.set(dst, at, v);
    }
}
