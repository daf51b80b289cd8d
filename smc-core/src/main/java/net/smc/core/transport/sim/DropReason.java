package net.smc.core.transport.sim;

/** Why the {@link InMemoryNetwork} dropped a datagram copy; each has its own counter in {@link NodeCounters}. */
public enum DropReason {
    /** The link's loss probability struck. Counted at the destination. */
    LOSS,
    /** A partition separates sender and destination. Counted at the destination. */
    PARTITION,
    /** The {@link RadioModel} says the destination is out of reach. Counted at the destination. */
    RADIO,
    /** The sender had crashed. Counted at the sender. */
    SENDER_DOWN,
    /** Nothing was attached at the destination when the copy arrived (crashed, closed, or never there). Counted at the destination. */
    RECEIVER_DOWN,
    /** The destination had not set a receiver yet. Counted at the destination. */
    NO_RECEIVER
}
