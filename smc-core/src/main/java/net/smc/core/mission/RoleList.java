package net.smc.core.mission;

import java.util.AbstractList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.RandomAccess;

/**
 * A mission's roles: an unmodifiable list, equal to any list of the same roles in the same order
 * (as {@link List#copyOf} would be), that also finds a role by name in constant time. A generated
 * mission has a thousand roles and more, and the team protocols look roles up by name for every
 * message they handle.
 */
final class RoleList extends AbstractList<MissionRole> implements RandomAccess {
    private final MissionRole[] roles;
    private final Map<String, MissionRole> byName;

    private RoleList(MissionRole[] roles) {
        this.roles = roles;
        this.byName = new HashMap<>(roles.length * 2);
        for (MissionRole r : roles) {
            byName.putIfAbsent(r.name(), r);   // the first of a name, as a search in order finds it
        }
    }

    /** The roles of {@code roles}, in order; no element may be null. */
    static RoleList of(List<MissionRole> roles) {
        if (roles instanceof RoleList list) {
            return list;
        }
        MissionRole[] copy = roles.toArray(new MissionRole[0]);
        for (int i = 0; i < copy.length; i++) {
            Objects.requireNonNull(copy[i], "role " + i + " of the mission's roles");
        }
        return new RoleList(copy);
    }

    /** The role called {@code name}, or null. */
    MissionRole named(String name) {
        return byName.get(name);
    }

    @Override
    public MissionRole get(int index) {
        return roles[index];
    }

    @Override
    public int size() {
        return roles.length;
    }
}
