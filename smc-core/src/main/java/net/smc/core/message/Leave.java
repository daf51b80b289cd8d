package net.smc.core.message;

/** Announces that the sender leaves its team (a shutdown, a withdrawn role), with a short reason. */
public record Leave(String reason) implements Message {
    public Leave {
        Fields.text("Leave.reason", reason);
    }

    @Override
    public MessageType type() {
        return MessageType.LEAVE;
    }
}
