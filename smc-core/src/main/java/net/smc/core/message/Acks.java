package net.smc.core.message;

import java.util.List;

/**
 * Confirms receipt of several messages at once (reliable delivery): each id in {@code acked} names
 * a message from the receiver of this one, exactly as an {@link Ack} would. The receiver of a burst
 * of critical messages answers them with one {@code Acks} datagram instead of one Ack each.
 *
 * <p>Holds 1 to {@link WireFormat#MAX_ACKS} ids, so that it always fits one datagram; an id may
 * appear more than once (a duplicate that arrived twice in the same burst is acknowledged twice).
 */
public record Acks(List<Long> acked) implements Message {
    public Acks {
        acked = Fields.list("Acks.acked", acked, WireFormat.MAX_ACKS);
        if (acked.isEmpty()) {
            throw new IllegalArgumentException("Acks.acked is empty; it must name 1 to " + WireFormat.MAX_ACKS
                    + " ids");
        }
    }

    @Override
    public MessageType type() {
        return MessageType.ACKS;
    }
}
