package net.smc.core.message;

import net.smc.core.wire.ByteWriter;

/**
 * The fixed header in front of every datagram:
 * <pre>
 *   magic 2 | version 1 | type 1 | sender length 1 | sender 1..64 | message id 8 | payload length 2
 * </pre>
 * One instance is reused by the decoder to hold the fields of the datagram at hand; writing is
 * static, since the encoder writes the header after it knows the payload's length.
 */
final class Header {
    /** The type code as read: a {@link MessageType} code or {@link WireFormat#FRAGMENT_CODE}. */
    int typeCode;
    String sender;
    long id;
    int payloadLength;

    /** The header's length for a sender of {@code senderBytes} UTF-8 bytes. */
    static int length(int senderBytes) {
        return WireFormat.FIXED_HEADER + senderBytes;
    }

    /**
     * Writes a header at {@code at}; the sender's {@code senderBytes} come from {@link Utf8#length}.
     * Returns the position after it, where the payload starts.
     */
    static int write(byte[] dst, int at, int typeCode, String sender, int senderBytes, long id, int payloadLength) {
        ByteWriter.putU16(dst, at, WireFormat.MAGIC);
        dst[at + 2] = (byte) WireFormat.VERSION;
        dst[at + 3] = (byte) typeCode;
        dst[at + 4] = (byte) senderBytes;
        int p = Utf8.encode(sender, dst, at + 5);
        ByteWriter.putI64(dst, p, id);
        ByteWriter.putU16(dst, p + 8, payloadLength);
        return p + 10;
    }

    /**
     * Reads and checks a header: magic, version and type first (so that a stranger's datagram or a
     * newer format is named as such), then the sender and id, then that the payload length is
     * exactly what remains of the datagram.
     */
    void read(DatagramReader r) throws DecodeException {
        sender = null;
        int magic = r.u16("magic");
        if (magic != WireFormat.MAGIC) {
            throw new DecodeException(RejectReason.BAD_MAGIC, String.format(
                    "magic is 0x%04X; a datagram starts with 0x%04X", magic, WireFormat.MAGIC));
        }
        int version = r.u8("version");
        if (version != WireFormat.VERSION) {
            throw new DecodeException(RejectReason.UNKNOWN_VERSION, "version is " + version
                    + "; this build reads version " + WireFormat.VERSION);
        }
        typeCode = r.u8("type");
        if (typeCode != WireFormat.FRAGMENT_CODE && MessageType.byCode(typeCode) == null) {
            throw new DecodeException(RejectReason.UNKNOWN_TYPE, String.format(
                    "type code 0x%02X is not assigned to a message type", typeCode));
        }
        String s = r.string8("sender", WireFormat.MAX_SENDER);
        id = r.i64("message id");
        sender = s;
        payloadLength = r.u16("payload length");
        int remaining = r.remaining();
        if (payloadLength > remaining) {
            throw new DecodeException(RejectReason.TRUNCATED, "payload length is " + payloadLength + " but "
                    + remaining + " bytes follow the header");
        }
        if (payloadLength < remaining) {
            throw new DecodeException(RejectReason.MALFORMED, "payload length is " + payloadLength + " but "
                    + remaining + " bytes follow the header");
        }
    }

    /** The type code as text for error messages. */
    String typeName() {
        MessageType t = MessageType.byCode(typeCode);
        return t != null ? t.name() : typeCode == WireFormat.FRAGMENT_CODE ? "FRAGMENT" : "type " + typeCode;
    }
}
