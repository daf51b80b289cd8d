package net.smc.core.message;

import net.smc.core.wire.ByteWriter;

/**
 * The header in front of every datagram:
 * <pre>
 *   magic 2 | version 1 | type 1 | sender length 1 | sender 0..64 | message id 8
 * </pre>
 * The payload is the rest of the datagram. A sender length of 0 leaves the sender to the transport:
 * one that proves who sent each datagram (an authenticating transport) names it, and the sender
 * would only repeat it. One instance is reused by the decoder to hold the fields of the datagram at
 * hand; writing is static, since the encoder writes the header after the payload.
 */
final class Header {
    /** The type code as read: a {@link MessageType} code or {@link WireFormat#FRAGMENT_CODE}. */
    int typeCode;
    String sender;
    long id;

    /** The header's length for a sender of {@code senderBytes} UTF-8 bytes (0: left to the transport). */
    static int length(int senderBytes) {
        return WireFormat.FIXED_HEADER + senderBytes;
    }

    /**
     * Writes a header at {@code at}; the sender's {@code senderBytes} come from {@link Utf8#length},
     * and a null sender (with {@code senderBytes} 0) is left to the transport. Returns the position
     * after it, where the payload starts.
     */
    static int write(byte[] dst, int at, int typeCode, String sender, int senderBytes, long id) {
        ByteWriter.putU16(dst, at, WireFormat.MAGIC);
        dst[at + 2] = (byte) WireFormat.VERSION;
        dst[at + 3] = (byte) typeCode;
        dst[at + 4] = (byte) senderBytes;
        int p = sender == null ? at + 5 : Utf8.encode(sender, dst, at + 5);
        ByteWriter.putI64(dst, p, id);
        return p + 8;
    }

    /**
     * Reads and checks a header: magic, version and type first (so that a stranger's datagram or a
     * newer format is named as such), then the sender and id. A header that leaves its sender to the
     * transport takes {@code namedSender}, the one the transport names; with none (null) it is refused.
     */
    void read(DatagramReader r, String namedSender) throws DecodeException {
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
        String s = r.senderOrNone("sender", WireFormat.MAX_SENDER);
        if (s == null && namedSender == null) {
            throw new DecodeException(RejectReason.MALFORMED, "the sender length is 0, which leaves the sender to"
                    + " a transport that proves it, and this datagram came without one");
        }
        id = r.i64("message id");
        sender = s != null ? s : namedSender;
    }

    /** The type code as text for error messages. */
    String typeName() {
        MessageType t = MessageType.byCode(typeCode);
        return t != null ? t.name() : typeCode == WireFormat.FRAGMENT_CODE ? "FRAGMENT" : "type " + typeCode;
    }
}
