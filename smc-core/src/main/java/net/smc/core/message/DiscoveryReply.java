package net.smc.core.message;

import net.smc.core.capability.CapabilitySummary;

/**
 * A vehicle's answer to a {@link Discovery}: the mission it answers, the role it holds now, and the
 * summary of its capabilities, from which the broadcaster decides whether to ask for the full
 * description.
 *
 * @param holds the role of the seat the vehicle holds now, empty when it is free: a vehicle with a
 *              parent answers another manager only as a candidate for a role ranked before its
 *              own (moving up), and takes no other seat from it
 */
public record DiscoveryReply(long inReplyTo, String mission, String holds, CapabilitySummary summary) implements Message {
    public DiscoveryReply {
        Fields.name("DiscoveryReply.mission", mission);
        Fields.string("DiscoveryReply.holds", holds, 0, WireFormat.MAX_NAME, "the role held (empty when free)");
        CapabilityLimits.summary("DiscoveryReply.summary", summary);
    }

    /** The answer of a free vehicle. */
    public DiscoveryReply(long inReplyTo, String mission, CapabilitySummary summary) {
        this(inReplyTo, mission, "", summary);
    }

    @Override
    public MessageType type() {
        return MessageType.DISCOVERY_REPLY;
    }
}
