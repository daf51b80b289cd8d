package net.smc.core.message;

import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import java.nio.ByteOrder;

/**
 * Writes fields big-endian into a byte array the encoder owns, between a start and a limit. Going
 * past the limit means the message is larger than {@link WireFormat#MAX_PAYLOAD}; the writer then
 * throws {@link Overflow}, which the encoder turns into an error naming the message.
 */
final class WireWriter {
    private static final VarHandle I16 = MethodHandles.byteArrayViewVarHandle(short[].class, ByteOrder.BIG_ENDIAN);
    private static final VarHandle I32 = MethodHandles.byteArrayViewVarHandle(int[].class, ByteOrder.BIG_ENDIAN);
    private static final VarHandle I64 = MethodHandles.byteArrayViewVarHandle(long[].class, ByteOrder.BIG_ENDIAN);

    /** Thrown when a payload does not fit; carries nothing, so one instance serves. */
    static final class Overflow extends RuntimeException {
        private static final long serialVersionUID = 1L;
        static final Overflow INSTANCE = new Overflow();

        private Overflow() {
            super("payload overflow", null, false, false);
        }
    }

    private final byte[] buf;
    private int pos;
    private int limit;

    WireWriter(byte[] buf) {
        this.buf = buf;
    }

    byte[] array() {
        return buf;
    }

    void reset(int start, int limit) {
        this.pos = start;
        this.limit = limit;
    }

    int position() {
        return pos;
    }

    void u8(int v) {
        ensure(1);
        buf[pos++] = (byte) v;
    }

    void u16(int v) {
        ensure(2);
        I16.set(buf, pos, (short) v);
        pos += 2;
    }

    void i32(int v) {
        ensure(4);
        I32.set(buf, pos, v);
        pos += 4;
    }

    void i64(long v) {
        ensure(8);
        I64.set(buf, pos, v);
        pos += 8;
    }

    void bool(boolean v) {
        u8(v ? 1 : 0);
    }

    /** A string with a one-byte length: records guarantee it is well formed and at most 255 bytes. */
    void string8(String s) {
        int len = Utf8.length(s);
        ensure(1 + len);
        buf[pos++] = (byte) len;
        pos = Utf8.encode(s, buf, pos);
    }

    /** A string with a two-byte length. */
    void string16(String s) {
        int len = Utf8.length(s);
        ensure(2 + len);
        I16.set(buf, pos, (short) len);
        pos = Utf8.encode(s, buf, pos + 2);
    }

    void bytes(byte[] src) {
        ensure(src.length);
        System.arraycopy(src, 0, buf, pos, src.length);
        pos += src.length;
    }

    private void ensure(int n) {
        if (limit - pos < n) {
            throw Overflow.INSTANCE;
        }
    }

    /** Writes a big-endian short into {@code dst} at {@code at}: for headers written after their payload. */
    static void putU16(byte[] dst, int at, int v) {
        I16.set(dst, at, (short) v);
    }

    static void putI32(byte[] dst, int at, int v) {
        I32.set(dst, at, v);
    }

    static void putI64(byte[] dst, int at, long v) {
        I64.set(dst, at, v);
    }
}
