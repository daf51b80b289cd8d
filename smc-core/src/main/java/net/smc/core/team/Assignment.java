package net.smc.core.team;

import java.util.List;
import java.util.Objects;

/**
 * The roles one vehicle holds. The first is the role it is anchored at: a primary role, or a
 * secondary role on a vehicle of its own; any others are secondary roles it carries beside that
 * primary until vehicles of their own join.
 *
 * @param vehicle the vehicle's id
 * @param roles   its roles, anchor first, then the others in the mission's role order; never empty
 */
public record Assignment(String vehicle, List<String> roles) {

    public Assignment {
        Objects.requireNonNull(vehicle, "vehicle");
        roles = List.copyOf(roles);
        if (roles.isEmpty()) {
            throw new IllegalArgumentException("vehicle '" + vehicle + "' is assigned no role; a spare vehicle has no assignment");
        }
    }

    /** The role the vehicle is anchored at. */
    public String anchor() {
        return roles.get(0);
    }

    /** Whether the vehicle carries secondary roles beside its anchor role. */
    public boolean isShared() {
        return roles.size() > 1;
    }
}
