package net.smc.core.message;

import java.io.ByteArrayOutputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;

/** Builds datagrams byte by byte, valid or not, for the decoder's tests. */
final class Raw {
    int magic = WireFormat.MAGIC;
    int version = WireFormat.VERSION;
    int type;
    byte[] sender = "uav1".getBytes(StandardCharsets.UTF_8);
    long id = 7;
    private final ByteArrayOutputStream bytes = new ByteArrayOutputStream();
    private final DataOutputStream payload = new DataOutputStream(bytes);

    Raw(int type) {
        this.type = type;
    }

    Raw(MessageType type) {
        this(type.code());
    }

    static Raw of(MessageType type) {
        return new Raw(type);
    }

    Raw u8(int v) {
        return io(() -> payload.writeByte(v));
    }

    Raw u16(int v) {
        return io(() -> payload.writeShort(v));
    }

    Raw i32(int v) {
        return io(() -> payload.writeInt(v));
    }

    Raw i64(long v) {
        return io(() -> payload.writeLong(v));
    }

    /** A string with a one-byte length. */
    Raw str8(String s) {
        byte[] b = s.getBytes(StandardCharsets.UTF_8);
        return u8(b.length).raw(b);
    }

    Raw raw(byte... b) {
        return io(() -> payload.write(b));
    }

    byte[] datagram() {
        byte[] p = bytes.toByteArray();
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        DataOutputStream d = new DataOutputStream(out);
        try {
            d.writeShort(magic);
            d.writeByte(version);
            d.writeByte(type);
            d.writeByte(sender.length);
            d.write(sender);
            d.writeLong(id);
            d.write(p);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return out.toByteArray();
    }

    private interface Io {
        void run() throws IOException;
    }

    private Raw io(Io io) {
        try {
            io.run();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return this;
    }
}
