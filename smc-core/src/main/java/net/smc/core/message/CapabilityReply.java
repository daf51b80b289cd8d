package net.smc.core.message;

import net.smc.core.capability.CapabilityDescription;

/**
 * The full capability description of a vehicle, answering a {@link CapabilityRequest}. A large
 * description travels in fragments.
 */
public record CapabilityReply(long inReplyTo, CapabilityDescription description) implements Message {
    public CapabilityReply {
        CapabilityLimits.description("CapabilityReply.description", description);
    }

    @Override
    public MessageType type() {
        return MessageType.CAPABILITY_REPLY;
    }
}
