package net.smc.core.mission;

import java.util.ArrayList;
import java.util.Collection;
import java.util.Collections;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.Set;

/**
 * A mission ready to run: a mission class instantiated by a mission instance (the paper's levels 2
 * and 3), every policy URI resolved. It is what the acting commander plans its team from
 * ({@link net.smc.core.team.TeamPlanner}) and what role assignment reads roles from. Load one with
 * {@link MissionLoader}; the constructor is for code that builds missions itself (tests,
 * benchmarks, experiments that vary the number of roles) and checks the same structure the loader
 * does, without positions.
 *
 * @param className    the mission class's name ({@code Reconnaissance})
 * @param instanceName the instance's name ({@code HouseSeven})
 * @param roles        the roles in the class file's order; the first is not necessarily the commander
 * @param colocation   which roles may share a vehicle
 * @param parameters   the parameters by name, in the class file's order
 */
public record Mission(String className, String instanceName, List<MissionRole> roles, Colocation colocation,
                      Map<String, Parameter> parameters) {
    /** The role at the root of every management tree. */
    public static final String COMMANDER = "commander";

    /**
     * @throws IllegalArgumentException naming the role and the rule when two roles share a name,
     *                                  the roles do not form a tree rooted at the commander, or a
     *                                  colocation rule or primary names an unknown or unfit role
     */
    public Mission {
        Objects.requireNonNull(className, "className");
        Objects.requireNonNull(instanceName, "instanceName");
        Objects.requireNonNull(colocation, "colocation");
        roles = RoleList.of(roles);
        parameters = Collections.unmodifiableMap(new LinkedHashMap<>(parameters));
        Set<String> names = new HashSet<>();
        for (MissionRole role : roles) {
            if (!names.add(role.name())) {
                throw new IllegalArgumentException("two roles are called '" + role.name() + "'; role names are unique");
            }
        }
        ManagementTree.of(roles);
        colocation.namedRoles().filter(r -> !names.contains(r)).findFirst().ifPresent(r -> {
            throw new IllegalArgumentException("a colocation rule names unknown role '" + r + "'");
        });
        checkPrimaries(roles, colocation);
    }

    private static void checkPrimaries(List<MissionRole> roles, Colocation colocation) {
        for (MissionRole role : roles) {
            if (role.primary().isEmpty()) {
                continue;
            }
            String primary = role.primary().get();
            MissionRole manager = roles.stream().filter(r -> r.name().equals(primary)).findFirst()
                    .orElseThrow(() -> new IllegalArgumentException("role '" + role.name() + "' is secondary to unknown role '"
                            + primary + "'"));
            if (manager.isSecondary()) {
                throw new IllegalArgumentException("role '" + role.name() + "' is secondary to '" + primary
                        + "', which is itself secondary; a primary role is not secondary");
            }
            if (!manager.manages().contains(role.name())) {
                throw new IllegalArgumentException("role '" + role.name() + "' is secondary to '" + primary
                        + "', which does not manage it; a primary role manages its secondary roles");
            }
            if (!colocation.mayShare(role.name(), primary)) {
                throw new IllegalArgumentException("role '" + role.name() + "' is secondary to '" + primary
                        + "', but no parallel or exclusive rule lets them share a vehicle");
            }
        }
    }

    /** The role called {@code name}. */
    public Optional<MissionRole> role(String name) {
        return Optional.ofNullable(((RoleList) roles).named(name));
    }

    /** The commander role (there always is one). */
    public MissionRole commander() {
        return role(COMMANDER).orElseThrow();
    }

    /** The management tree the roles form. */
    public ManagementTree tree() {
        return ManagementTree.of(roles);
    }

    /** The parameter called {@code name}. */
    public Optional<Parameter> parameter(String name) {
        return Optional.ofNullable(parameters.get(name));
    }

    /** The role names, in the class file's order. */
    public List<String> roleNames() {
        List<String> names = new ArrayList<>();
        roles.forEach(r -> names.add(r.name()));
        return names;
    }

    /**
     * Whether one vehicle may hold all of {@code held} at once: one role; or one primary role
     * together with secondary roles of that primary, every two of them allowed to share a vehicle
     * by a parallel or exclusive rule. Unknown role names are never allowed.
     */
    public boolean allowsOnOneVehicle(Collection<String> held) {
        List<String> list = List.copyOf(new java.util.LinkedHashSet<>(held));
        if (list.size() != held.size() || list.stream().anyMatch(r -> role(r).isEmpty())) {
            return false;
        }
        if (list.size() <= 1) {
            return true;
        }
        List<String> primaries = list.stream().filter(r -> !role(r).orElseThrow().isSecondary()).toList();
        if (primaries.size() != 1) {
            return false;
        }
        String primary = primaries.get(0);
        for (String r : list) {
            if (!r.equals(primary) && !role(r).orElseThrow().primary().orElseThrow().equals(primary)) {
                return false;
            }
        }
        for (int i = 0; i < list.size(); i++) {
            for (int j = i + 1; j < list.size(); j++) {
                if (!colocation.mayShare(list.get(i), list.get(j))) {
                    return false;
                }
            }
        }
        return true;
    }
}
