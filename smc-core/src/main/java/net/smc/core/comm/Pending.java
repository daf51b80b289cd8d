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
    /** Transmissions so far, the first included. */
    int tries;
    /** When the current try times out. */
    long deadlineMillis;
    /** Acked or failed: any timer entry still naming it is stale. */
    boolean settled;

    Pending(long id, Address to, MessageType type, List<byte[]> datagrams, DeliveryListener listener,
            long firstSentMillis) {
        this.id = id;
        this.to = to;
        this.type = type;
        this.datagrams = datagrams;
        this.listener = listener;
        this.firstSentMillis = firstSentMillis;
    }

    @Override
    public String toString() {
        return type + " id " + id + " to " + to + " (try " + tries + ")";
    }
}
