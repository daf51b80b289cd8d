package net.smc.core.message;

import java.util.Comparator;

/**
 * A vehicle's identity in a team, the paper's {@code I = [M | H | S]}: the mission, the level of
 * the vehicle in the management tree (0 for the commander) and a sequence number. Identities are
 * totally ordered (mission, then level, then sequence), which lets partitioned teams agree on who
 * leads when they merge without another round of messages.
 */
public record Identity(String mission, int level, int sequence) implements Comparable<Identity> {
    private static final Comparator<Identity> ORDER = Comparator.comparing(Identity::mission)
            .thenComparingInt(Identity::level).thenComparingInt(Identity::sequence);

    public Identity {
        Fields.name("Identity.mission", mission);
        Fields.nonNegative("Identity.level", level);
        Fields.nonNegative("Identity.sequence", sequence);
    }

    @Override
    public int compareTo(Identity other) {
        return ORDER.compare(this, other);
    }

    /** {@code [mission|level|sequence]}, as the paper writes it. */
    @Override
    public String toString() {
        return "[" + mission + "|" + level + "|" + sequence + "]";
    }
}
