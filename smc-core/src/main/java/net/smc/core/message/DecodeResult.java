package net.smc.core.message;

/**
 * What {@link MessageDecoder#decode} made of one datagram: a whole message, a fragment held until
 * its siblings arrive, or a rejection with its reason. The decoder never throws instead.
 */
public sealed interface DecodeResult {

    /** A complete message (from one datagram, or reassembled from fragments). */
    record Decoded(Envelope envelope) implements DecodeResult {
    }

    /** A fragment was stored; {@code received} of {@code count} fragments of the message are in. */
    record FragmentPending(String sender, long id, MessageType type, int received, int count) implements DecodeResult {
    }

    /** The datagram was discarded (and counted); {@code detail} names the field, the value and the rule. */
    record Rejected(RejectReason reason, String detail) implements DecodeResult {
    }
}
