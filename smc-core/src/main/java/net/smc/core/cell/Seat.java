package net.smc.core.cell;

/**
 * One place in a team configuration: a role and one of its slots. A role of optimal cardinality
 * {@code n} has slots {@code 0 .. n-1}; a slot has at most one holder, which is what keeps a team at
 * or below its reasonably-optimal configuration. Slots below the role's minimal cardinality are the
 * ones the minimal configuration needs.
 */
public record Seat(String role, int slot) implements Comparable<Seat> {
    public Seat {
        if (role == null || role.isEmpty()) {
            throw new IllegalArgumentException("a seat needs a role name");
        }
        if (slot < 0) {
            throw new IllegalArgumentException("seat of role '" + role + "' has slot " + slot + "; slots start at 0");
        }
    }

    @Override
    public int compareTo(Seat o) {
        int c = role.compareTo(o.role);
        return c != 0 ? c : Integer.compare(slot, o.slot);
    }

    @Override
    public String toString() {
        return role + "#" + slot;
    }
}
