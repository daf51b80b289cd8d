package net.smc.core.comm;

/**
 * Learns the outcome of one critical message sent by the {@link MessageSender}. Exactly one of the
 * two methods fires, once, on the cell's thread, never inside the {@code send} call that started
 * the message. An exception thrown here is logged and does not disturb the sender.
 *
 * <p>"Failed" means the sender stopped trying, not that the peer never got the message: the
 * message may have arrived and every Ack been lost. Protocols that must know decide at a higher
 * level (an AssignmentResponse, say).
 */
public interface DeliveryListener {

    /** A listener that ignores both outcomes. */
    DeliveryListener IGNORE = new DeliveryListener() {
    };

    /** Fires when the peer's Ack for message {@code id} arrives (the first one, if several do). */
    default void delivered(long id) {
    }

    /** Fires when the sender gives up on message {@code id}, with the reason. */
    default void failed(long id, FailureReason reason) {
    }
}
