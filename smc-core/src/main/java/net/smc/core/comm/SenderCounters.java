package net.smc.core.comm;

/**
 * What one cell's {@link MessageSender} has done, both as sender and as receiver of critical
 * messages. Read on the cell's thread (or after it stopped). In a quiet network
 * {@code sent == acked + failed + outstanding}; {@code delivered + duplicates} counts every
 * critical copy received, and each of them was acknowledged ({@code acksSent}).
 */
public final class SenderCounters {
    long sent;
    long acked;
    long retransmitted;
    long fastRetransmitted;
    long probes;
    long failed;
    long unknownAcks;
    long misdirectedAcks;
    long delivered;
    long duplicates;
    long acksSent;
    long ackDatagrams;

    SenderCounters() {
    }

    /** Critical messages sent (first transmissions). */
    public long sent() {
        return sent;
    }

    /** Critical messages whose Ack arrived. */
    public long acked() {
        return acked;
    }

    /** Retransmissions: transmissions after the first, over all messages. */
    public long retransmitted() {
        return retransmitted;
    }

    /**
     * Of the retransmissions, those sent before their timeout because a message sent after them to the
     * same peer was acknowledged first ({@code LossDetector}).
     */
    public long fastRetransmitted() {
        return fastRetransmitted;
    }

    /**
     * Of the retransmissions, tail probes: the last message sent to a peer, sent again (an extra copy,
     * not a try) when neither its Ack nor another message to the peer came within two round trips.
     */
    public long probes() {
        return probes;
    }

    /** Critical messages given up on (reported to their listener as failed). */
    public long failed() {
        return failed;
    }

    /** Acks for no outstanding message: a duplicated or late Ack, after the first one settled it. */
    public long unknownAcks() {
        return unknownAcks;
    }

    /** Acks for an outstanding message that came from another address than the one it was sent to; ignored. */
    public long misdirectedAcks() {
        return misdirectedAcks;
    }

    /** Critical messages received for the first time and handed on to the application. */
    public long delivered() {
        return delivered;
    }

    /** Critical messages received again (retransmitted or duplicated) and suppressed; each was acknowledged again. */
    public long duplicates() {
        return duplicates;
    }

    /** Acks sent by this cell as a receiver. */
    public long acksSent() {
        return acksSent;
    }

    /** Datagrams that carried acknowledgements (an Ack or a coalesced Acks); at most {@link #acksSent()}. */
    public long ackDatagrams() {
        return ackDatagrams;
    }

    @Override
    public String toString() {
        return "sent=" + sent + " acked=" + acked + " retransmitted=" + retransmitted + " (fast " + fastRetransmitted + ") failed=" + failed
                + " unknownAcks=" + unknownAcks + " misdirectedAcks=" + misdirectedAcks + " delivered=" + delivered
                + " duplicates=" + duplicates + " acksSent=" + acksSent + " ackDatagrams=" + ackDatagrams;
    }
}
