package net.smc.core.message;

import java.util.List;

/**
 * What a parent tells its child, every heartbeat period and in answer to each heartbeat: the
 * mission, the parent's identity, the acting commander's vehicle id, the team's epoch, the team
 * size, the echo: the envelope id of the child's latest heartbeat the parent has heard (0 when
 * none), the parent's ancestors (its own parent first, up to the commander), and the version of
 * this content (all but the echo) at the parent: it grows whenever the content changes, a child
 * names the version it holds in its heartbeats, and while that is the current one the parent
 * answers with a bare {@link Echo} instead (0: no version, always answered in full). The echo is what renews the child's lease: the parent cannot declare the child failed
 * before a failure timeout has passed since that heartbeat was sent.
 */
public record Status(String mission, Identity identity, String commander, long epoch, int teamSize, long echo,
                     List<String> ancestors, long version) implements Message {
    /** A status that echoes no heartbeat. */
    public Status(String mission, Identity identity, String commander, long epoch, int teamSize) {
        this(mission, identity, commander, epoch, teamSize, 0, List.of());
    }

    /** A status of no version (0): the child's heartbeats will not name it, so each is answered in full. */
    public Status(String mission, Identity identity, String commander, long epoch, int teamSize, long echo,
                  List<String> ancestors) {
        this(mission, identity, commander, epoch, teamSize, echo, ancestors, 0);
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
        Fields.nonNegative("Status.version", version);
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
