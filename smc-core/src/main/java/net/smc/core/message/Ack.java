package net.smc.core.message;

/** Confirms receipt of the message with id {@code acked} from the receiver of this one (reliable delivery). */
public record Ack(long acked) implements Message {
    @Override
    public MessageType type() {
        return MessageType.ACK;
    }
}
