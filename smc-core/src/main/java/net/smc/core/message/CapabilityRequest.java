package net.smc.core.message;

/**
 * Asks a vehicle that answered a discovery for its full capability description, because its
 * summary looked viable for {@code role}. Answered by a {@link CapabilityReply}.
 */
public record CapabilityRequest(String role) implements Message {
    public CapabilityRequest {
        Fields.name("CapabilityRequest.role", role);
    }

    @Override
    public MessageType type() {
        return MessageType.CAPABILITY_REQUEST;
    }
}
