package net.smc.core.message;

/**
 * One message as it travels: who sent it, its id and its body. The sender is the sending vehicle's
 * id (1 to 64 UTF-8 bytes); the id is unique per sender, so that {@code (sender, id)} names one
 * message: replies refer to it, acknowledgements confirm it, the reassembler joins its fragments
 * by it and receivers suppress duplicates by it.
 */
public record Envelope(String sender, long id, Message body) {
    public Envelope {
        Fields.string("Envelope.sender", sender, 1, WireFormat.MAX_SENDER, "a vehicle id");
        Fields.present("Envelope.body", body);
    }

    /** The type of the body. */
    public MessageType type() {
        return body.type();
    }
}
