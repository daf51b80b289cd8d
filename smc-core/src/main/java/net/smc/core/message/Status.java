package net.smc.core.message;

import java.util.List;

/**
 * What a parent tells its child, every heartbeat period and in answer to each heartbeat: the
 * mission, the parent's identity, the acting commander's vehicle id, the team's epoch, the team
 * size, the echo: the envelope id of the child's latest heartbeat the parent has heard (0 when
 * none), and the parent's ancestors (its own parent first, up to the commander). The echo is what renews the child's lease: the parent cannot declare the child failed
 * before a failure timeout has passed since that heartbeat was sent.
 */
public record Status(String mission, Identity identity, String commander, long epoch, int teamSize, long echo,
                     List<String> ancestors) implements Message {
    /** A status that echoes no heartbeat. */
    public Status(String mission, Identity identity, String commander, long epoch, int teamSize) {
        this(mission, identity, commander, epoch, teamSize, 0, List.of());
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
        ancestors = Fields.list("Status.ancestors", ancestors, RoleAssignment.MAX_ANCESTORS);
        for (String a : ancestors) {
            Fields.string("Status.ancestors[]", a, 1, WireFormat.MAX_SENDER, "a vehicle id");
        }
    }

    @Override
    public MessageType type() {
        return MessageType.STATUS;
    }
}
