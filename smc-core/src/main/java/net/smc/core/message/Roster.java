package net.smc.core.message;

import java.util.List;

/**
 * The acting commander's team roster, replicated to its backup commanders so that one of them can
 * take over the commander's children when the commander fails. The sender is the commander.
 *
 * @param mission the mission
 * @param epoch   the team configuration's epoch; a backup that takes over leads epoch + 1
 * @param backups the backup commanders, in the order they take over
 * @param members the commander's children: one entry per role and slot each holds
 */
public record Roster(String mission, long epoch, List<String> backups, List<Entry> members) implements Message {
    /** The most entries one roster carries. */
    public static final int MAX_MEMBERS = 1_024;
    /** The most backups one roster names. */
    public static final int MAX_BACKUPS = 16;

    public Roster {
        Fields.name("Roster.mission", mission);
        Fields.nonNegative("Roster.epoch", epoch);
        backups = Fields.list("Roster.backups", backups, MAX_BACKUPS);
        for (String b : backups) {
            Fields.string("Roster.backups[]", b, 1, WireFormat.MAX_SENDER, "a vehicle id");
        }
        members = Fields.list("Roster.members", members, MAX_MEMBERS);
    }

    @Override
    public MessageType type() {
        return MessageType.ROSTER;
    }

    /**
     * One child of the commander: the vehicle, where it is reached, and one role it holds there.
     *
     * @param address its address as {@code host:port}
     * @param slot    the slot of the role it holds (0 to the role's optimal cardinality - 1)
     */
    public record Entry(String vehicle, String address, String role, int slot) {
        public Entry {
            Fields.string("Roster.Entry.vehicle", vehicle, 1, WireFormat.MAX_SENDER, "a vehicle id");
            Fields.string("Roster.Entry.address", address, 1, WireFormat.MAX_TEXT, "host:port");
            Fields.name("Roster.Entry.role", role);
            Fields.nonNegative("Roster.Entry.slot", slot);
        }
    }
}
