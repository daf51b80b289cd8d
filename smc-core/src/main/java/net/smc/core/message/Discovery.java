package net.smc.core.message;

/**
 * Broadcast by a manager looking for vehicles to fill roles of its subtree: the mission, the
 * broadcaster's role and its level in the management tree, and the mission epoch (which grows
 * at every re-configuration, so that stale broadcasts can be told apart). Unassigned cells able to
 * hold a role that the broadcaster's role manages answer with a {@link DiscoveryReply}; the others,
 * and cells that already have a parent, stay quiet.
 */
public record Discovery(String mission, String role, int level, long epoch) implements Message {
    public Discovery {
        Fields.name("Discovery.mission", mission);
        Fields.name("Discovery.role", role);
        Fields.nonNegative("Discovery.level", level);
        Fields.nonNegative("Discovery.epoch", epoch);
    }

    @Override
    public MessageType type() {
        return MessageType.DISCOVERY;
    }
}
