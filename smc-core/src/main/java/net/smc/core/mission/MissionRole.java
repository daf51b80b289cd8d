package net.smc.core.mission;

import java.util.List;
import java.util.Objects;
import java.util.Optional;
import net.smc.core.capability.CapabilityRequirement;

/**
 * One role as a mission defines it: the class gives its name, what it manages, what a vehicle
 * needs to hold it and whether it is secondary; the instance gives its cardinalities and its
 * policies. (The role a vehicle loads, with its tasks and interfaces, is {@code net.smc.core.role.Role};
 * its policy sources are these URIs.)
 *
 * @param name        the role's name ({@code surveyor}); letters, digits and {@code _}, from a letter
 * @param minimal     holders the minimal team configuration needs (0 or more); the mission starts once every role has this many
 * @param optimal     holders of the reasonably-optimal configuration (1 or more, at least {@code minimal}); never exceeded
 * @param manages     the roles this role manages in the management tree, in the class file's order
 * @param requirement the resources and tasks a vehicle needs to hold this role
 * @param primary     for a secondary role, its primary role: a vehicle holding the primary may hold
 *                    this role too while no vehicle of its own is free
 * @param policies    the policy URIs of the role-mission ({@code policy:/roles/surveyor/mission}):
 *                    files that create the obligation policies that give the role its behaviour, in order
 * @param authorisations the policy URIs of the role's authorisations ({@code policy:/roles/surveyor/auth}):
 *                    files that create its authorisation policies, in order
 * @param interfaces  the events it publishes and subscribes to and the operations it offers and uses
 */
public record MissionRole(String name, int minimal, int optimal, List<String> manages, CapabilityRequirement requirement,
                          Optional<String> primary, List<String> policies, List<String> authorisations,
                          RoleInterface interfaces) {

    public MissionRole {
        Objects.requireNonNull(name, "name");
        Objects.requireNonNull(requirement, "requirement");
        Objects.requireNonNull(primary, "primary");
        manages = List.copyOf(manages);
        policies = List.copyOf(policies);
        authorisations = List.copyOf(authorisations);
        interfaces = interfaces == null ? RoleInterface.NONE : interfaces;
        if (minimal < 0 || optimal < 1 || minimal > optimal) {
            throw new IllegalArgumentException("role '" + name + "' has minimal " + minimal + " and optimal " + optimal
                    + "; they must satisfy 0 <= minimal <= optimal and optimal >= 1");
        }
    }

    /** A role without an external interface. */
    public MissionRole(String name, int minimal, int optimal, List<String> manages, CapabilityRequirement requirement,
                       Optional<String> primary, List<String> policies, List<String> authorisations) {
        this(name, minimal, optimal, manages, requirement, primary, policies, authorisations, RoleInterface.NONE);
    }

    /** Whether this role may ride on a vehicle of its primary role. */
    public boolean isSecondary() {
        return primary.isPresent();
    }

    /** {@code surveyor 2..2} style, for messages and listings. */
    public String cardinality() {
        return minimal + ".." + optimal;
    }
}
