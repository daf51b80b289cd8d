package net.smc.sim.experiment;

import java.nio.charset.StandardCharsets;

import net.smc.core.message.WireFormat;

/**
 * What {@link CpuCharge} reads of a datagram on the simulated network without decoding it: the
 * message header's type, id and named sender (wire-format note), and the fields of a policy reply
 * that say what loading it costs. Every read is bounded by the datagram; a field the datagram is too
 * short to hold reads as unknown.
 */
final class MessageHeaders {
    private static final int TYPE_OFFSET = 3;
    private static final int SENDER_LENGTH_OFFSET = 4;

    /** Where the encoded message starts in a datagram on the network (after the transport's seal, if any). */
    private final int payloadOffset;

    MessageHeaders(int payloadOffset) {
        this.payloadOffset = payloadOffset;
    }

    /** The message type of a datagram; for a fragment, the type of the message it is a piece of; -1 if unreadable. */
    int type(byte[] data) {
        int at = payloadOffset;
        if (data.length <= at + SENDER_LENGTH_OFFSET) {
            return -1;
        }
        int type = data[at + TYPE_OFFSET] & 0xFF;
        if (type != WireFormat.FRAGMENT_CODE) {
            return type;
        }
        int payload = at + WireFormat.FIXED_HEADER + (data[at + SENDER_LENGTH_OFFSET] & 0xFF);
        return payload < data.length ? data[payload] & 0xFF : -1;
    }

    /** What is read of a {@code PolicyReply}'s first datagram: the policy's URI, its text's UTF-8 length and coding. */
    record PolicyText(String uri, int version, int bytes, boolean deflated) {
    }

    /**
     * The policy a {@code PolicyReply} datagram carries (for a fragmented message, read from its
     * first fragment, which holds the fields before the text); null for a later fragment or a
     * datagram too short to hold them.
     */
    PolicyText policyText(byte[] data) {
        int at = payloadOffset;
        int payload = at + WireFormat.FIXED_HEADER + (data[at + SENDER_LENGTH_OFFSET] & 0xFF);
        if ((data[at + TYPE_OFFSET] & 0xFF) == WireFormat.FRAGMENT_CODE) {
            if (payload + WireFormat.FRAGMENT_HEADER > data.length || u16(data, payload + 1) != 0) {
                return null; // not the first fragment: the message was charged with that one
            }
            payload += WireFormat.FRAGMENT_HEADER;
        }
        int uriAt = payload + 8; // after the request id it answers
        if (uriAt >= data.length) {
            return null;
        }
        int n = data[uriAt] & 0xFF;
        int textAt = uriAt + 1 + n + 4; // after the URI and the version
        if (textAt + 3 > data.length) {
            return null;
        }
        int version = (data[textAt - 4] & 0xFF) << 24 | (data[textAt - 3] & 0xFF) << 16 | u16(data, textAt - 2);
        return new PolicyText(new String(data, uriAt + 1, n, StandardCharsets.UTF_8), version, u16(data, textAt),
                (data[textAt + 2] & 0xFF) != WireFormat.POLICY_TEXT_PLAIN);
    }

    private static int u16(byte[] b, int at) {
        return (b[at] & 0xFF) << 8 | (b[at + 1] & 0xFF);
    }

    /** The message id in a datagram's header (a fragment's: the whole message's), or -1 if unreadable. */
    long messageId(byte[] data) {
        int at = payloadOffset + SENDER_LENGTH_OFFSET + 1;
        if (data.length <= at) {
            return -1;
        }
        at += data[at - 1] & 0xFF;
        if (data.length < at + 8) {
            return -1;
        }
        long id = 0;
        for (int i = 0; i < 8; i++) {
            id = id << 8 | (data[at + i] & 0xFF);
        }
        return id;
    }

    /** The vehicle named as a datagram's sender, or "" if unreadable or left to the transport. */
    String sender(byte[] data) {
        int at = payloadOffset;
        if (data.length <= at + SENDER_LENGTH_OFFSET) {
            return "";
        }
        int n = data[at + SENDER_LENGTH_OFFSET] & 0xFF;
        return n <= data.length - at - SENDER_LENGTH_OFFSET - 1
                ? new String(data, at + SENDER_LENGTH_OFFSET + 1, n, StandardCharsets.UTF_8) : "";
    }
}
