package net.smc.core.comm;

import net.smc.core.message.RejectReason;

/**
 * What one cell's {@link CommunicationManager} has moved: messages and datagrams out, datagrams
 * in and what became of each. Every datagram received ends in exactly one of: an application
 * message dispatched, a duplicate suppressed, an Ack consumed, a fragment held, a spoofed message dropped, or a rejection, so
 * nothing is dropped without a count. Read on the cell's thread (or after it stopped).
 */
public final class CommCounters {
    long unicasts;
    long broadcasts;
    long datagramsSent;
    long datagramsReceived;
    long dispatched;
    long acksReceived;
    long fragmentsHeld;
    long spoofed;
    final long[] rejected = new long[RejectReason.values().length];

    CommCounters() {
    }

    /** Connectionless messages sent to one address (critical ones are counted by the {@link SenderCounters}). */
    public long unicasts() {
        return unicasts;
    }

    /** Messages broadcast. */
    public long broadcasts() {
        return broadcasts;
    }

    /** Datagrams handed to the transport: fragments, retransmissions and Acks included. */
    public long datagramsSent() {
        return datagramsSent;
    }

    /** Datagrams that arrived from the transport. */
    public long datagramsReceived() {
        return datagramsReceived;
    }

    /** Application messages handed to the Message-Router (each critical message once). */
    public long dispatched() {
        return dispatched;
    }

    /** Acks received (consumed by the Message-Sender, never dispatched). */
    public long acksReceived() {
        return acksReceived;
    }

    /** Fragments stored until the rest of their message arrives. */
    public long fragmentsHeld() {
        return fragmentsHeld;
    }

    /** Messages dropped because the envelope named another sender than the transport proved. */
    public long spoofed() {
        return spoofed;
    }

    /** Datagrams the decoder rejected, for any reason. */
    public long rejected() {
        long sum = 0;
        for (long r : rejected) {
            sum += r;
        }
        return sum;
    }

    /** Datagrams the decoder rejected for {@code reason}. */
    public long rejected(RejectReason reason) {
        return rejected[reason.ordinal()];
    }

    @Override
    public String toString() {
        return "unicasts=" + unicasts + " broadcasts=" + broadcasts + " datagramsSent=" + datagramsSent
                + " datagramsReceived=" + datagramsReceived + " dispatched=" + dispatched + " acksReceived="
                + acksReceived + " fragmentsHeld=" + fragmentsHeld + " spoofed=" + spoofed + " rejected=" + rejected();
    }
}
