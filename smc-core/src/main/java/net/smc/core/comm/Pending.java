package net.smc.core.comm;

import java.util.List;

import net.smc.core.message.MessageType;
import net.smc.core.transport.Address;

/**
 * One critical message waiting for its Ack: its encoded datagrams (kept, so a retransmission is
 * the same bytes and costs no encoding), where it goes, who wants the outcome, and how far the
 * retransmission has got. Mutated only by the {@link MessageSender}, on the cell's thread.
 */
final class Pending {
    final long id;
    final Address to;
    final MessageType type;
    final List<byte[]> datagrams;
    final DeliveryListener listener;
    final long firstSentMillis;
    /** The first try's timeout, fixed at the send (the round-trip estimate then); later tries back off from it. */
    final long firstTimeoutMillis;
    /** When the first copy left the transport ({@code Transport.backlogMillis}): round trips are measured from it. */
    long firstDepartureMillis;
    /** When the latest copy leaves the transport. */
    long departureMillis;
    /** Transmissions so far, the first included. */
    int tries;
    /** When the current try times out. */
    long deadlineMillis;
    /** Acked or failed: any timer entry still naming it is stale. */
    boolean settled;
    /** Taken for lost by the {@link LossDetector} (a message sent after it was acknowledged first). */
    boolean suspected;
    /** Sent again as its peer's tail probe ({@code MessageSender}): its Ack lets the loss detector look behind it. */
    boolean probed;
    /** When its tail probe is due for the current try; 0 when none is ({@code MessageSender}). */
    long probeAtMillis;

    Pending(long id, Address to, MessageType type, List<byte[]> datagrams, DeliveryListener listener,
            long firstSentMillis, long firstTimeoutMillis) {
        this.id = id;
        this.to = to;
        this.type = type;
        this.datagrams = datagrams;
        this.listener = listener;
        this.firstSentMillis = firstSentMillis;
        this.firstTimeoutMillis = firstTimeoutMillis;
    }

    @Override
    public String toString() {
        return type + " id " + id + " to " + to + " (try " + tries + ")";
    }
}
