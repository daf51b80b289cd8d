package net.smc.core.message;

/**
 * What a team member knows of its team: the mission, its identity, the acting commander's vehicle
 * id, the mission epoch and the team size. Cells compare statuses to notice partitions and to
 * decide merges.
 */
public record Status(String mission, Identity identity, String commander, long epoch, int teamSize)
        implements Message {
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
