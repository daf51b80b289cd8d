package net.smc.core.message;

/**
 * A free vehicle that is taking a role withdraws the answer it gave to another manager's
 * {@link Discovery} (named by {@code inReplyTo}): it is no longer free, and an assignment on that
 * answer would only be refused. Connectionless and unacknowledged, like the answer it withdraws.
 */
public record Withdrawal(long inReplyTo, String mission) implements Message {
    public Withdrawal {
        Fields.name("Withdrawal.mission", mission);
    }

    @Override
    public MessageType type() {
        return MessageType.WITHDRAWAL;
    }
}
