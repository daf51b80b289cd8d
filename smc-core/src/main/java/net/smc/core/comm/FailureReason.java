package net.smc.core.comm;

/** Why the {@link MessageSender} gave up on a critical message. */
public enum FailureReason {
    /** Every try of {@link SenderSettings#maxTries()} went unacknowledged: the peer is unreachable, crashed or too slow. */
    NO_ACK,
    /** The sender was stopped (its cell shut down or crashed) while the message was outstanding. */
    STOPPED,
    /** The transport refused a retransmission (closed under the sender); the cause is logged. */
    SEND_ERROR
}
