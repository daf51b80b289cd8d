package net.smc.core.message;

/**
 * The header of a fragment frame, after the datagram header: the original message type, the
 * fragment's index, the fragment count and the total payload length; the chunk is the rest of the
 * payload. {@link #read} checks a frame alone; the {@link Reassembler} checks it against its
 * siblings.
 */
record FragmentHeader(MessageType type, int index, int count, int total) {

    static FragmentHeader read(DatagramReader r) throws DecodeException {
        int code = r.u8("fragment type");
        int index = r.u16("fragment index");
        int count = r.u16("fragment count");
        int total = r.i32("fragment total");
        MessageType type = MessageType.byCode(code);
        if (type == null) {
            throw new DecodeException(code == WireFormat.FRAGMENT_CODE ? RejectReason.BAD_FRAGMENT
                    : RejectReason.UNKNOWN_TYPE, String.format("fragment type code 0x%02X is not a message type", code));
        }
        if (count > WireFormat.MAX_FRAGMENTS) {
            throw new DecodeException(RejectReason.OVERSIZED, "fragment count is " + count + "; at most "
                    + WireFormat.MAX_FRAGMENTS + " are allowed");
        }
        if (total < 0 || total > WireFormat.MAX_PAYLOAD) {
            throw new DecodeException(RejectReason.OVERSIZED, "fragment total is " + Integer.toUnsignedString(total)
                    + " bytes; a message is at most " + WireFormat.MAX_PAYLOAD);
        }
        if (count < 2) {
            throw new DecodeException(RejectReason.BAD_FRAGMENT, "fragment count is " + count
                    + "; a fragmented message has 2 or more");
        }
        if (index >= count) {
            throw new DecodeException(RejectReason.BAD_FRAGMENT, "fragment index is " + index + "; it must be below"
                    + " the count " + count);
        }
        int expected = Fragmenter.chunkLength(index, count, total);
        if (expected <= 0 || Fragmenter.chunkLength(count - 1, count, total) <= 0) {
            throw new DecodeException(RejectReason.BAD_FRAGMENT, count + " fragments cannot split " + total
                    + " bytes (the last chunk would be empty)");
        }
        if (r.remaining() != expected) {
            throw new DecodeException(RejectReason.BAD_FRAGMENT, "fragment " + index + " of " + count + " of a "
                    + total + "-byte " + type + " must carry " + expected + " bytes; it carries " + r.remaining());
        }
        return new FragmentHeader(type, index, count, total);
    }
}
