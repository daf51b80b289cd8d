package net.smc.core.message;

/**
 * What a parent tells its child, every heartbeat period and in answer to each heartbeat: the
 * mission, the parent's identity, the acting commander's vehicle id, the team's epoch, the team
 * size, and the echo: the envelope id of the child's latest heartbeat the parent has heard (0 when
 * none). The echo is what renews the child's lease: the parent cannot declare the child failed
 * before a failure timeout has passed since that heartbeat was sent.
 */
public record Status(String mission, Identity identity, String commander, long epoch, int teamSize, long echo)
        implements Message {
    /** A status that echoes no heartbeat. */
    public Status(String mission, Identity identity, String commander, long epoch, int teamSize) {
        this(mission, identity, commander, epoch, teamSize, 0);
    }

    public Status {
        Fields.name("Status.mission", mission);
        Fields.present("Status.identity", identity);
        if (!identity.mission().equals(mission)) {
            throw new IllegalArgumentException("Status.identity " + identity + " is for mission "
                    + Fields.show(identity.mission()) + "; it must be for the status's mission " + Fields.show(mission));
        }
        Fields.string("Status.commander", commander, 1, WireFormat.MAX_SENDER, "a vehicle id");
        Fields.nonNegative("Status.epoch", epoch);
        Fields.nonNegative("Status.teamSize", teamSize);
    }

    @Override
    public MessageType type() {
        return MessageType.STATUS;
    }
}
