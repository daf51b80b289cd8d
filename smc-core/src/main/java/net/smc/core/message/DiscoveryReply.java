package net.smc.core.message;

import net.smc.core.capability.CapabilitySummary;

/**
 * An unassigned vehicle's answer to a {@link Discovery}: the mission it answers and the summary of
 * its capabilities, from which the broadcaster decides whether to ask for the full description.
 */
public record DiscoveryReply(long inReplyTo, String mission, CapabilitySummary summary) implements Message {
    public DiscoveryReply {
        Fields.name("DiscoveryReply.mission", mission);
        CapabilityLimits.summary("DiscoveryReply.summary", summary);
    }

    @Override
    public MessageType type() {
        return MessageType.DISCOVERY_REPLY;
    }
}
