package net.smc.core.team;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import net.smc.core.capability.CapabilitySummary;
import net.smc.core.mission.Mission;
import net.smc.core.mission.MissionRole;

/** What every team configuration must satisfy, checked from the outside (mission rules, not planner internals). */
final class Invariants {
    private Invariants() {
    }

    static void check(Mission mission, List<CapabilitySummary> vehicles, TeamConfiguration team, String seed) {
        Map<String, CapabilitySummary> byId = new TreeMap<>();
        vehicles.forEach(v -> byId.put(v.vehicle(), v));
        List<String> seen = new ArrayList<>();
        team.assignments().forEach(a -> seen.add(a.vehicle()));
        seen.addAll(team.spare());
        assertEquals(List.copyOf(byId.keySet()), seen.stream().sorted().toList(), seed + ": every vehicle once");
        assertEquals(mission.roleNames(), List.copyOf(team.holders().keySet()), seed + ": every role, in order");
        boolean minimal = true;
        boolean optimal = true;
        for (MissionRole role : mission.roles()) {
            List<String> holders = team.holdersOf(role.name());
            assertTrue(holders.size() <= role.optimal(), seed + ": role " + role.name() + " has " + holders.size()
                    + " holders, more than its optimal " + role.optimal());
            minimal &= holders.size() >= role.minimal();
            optimal &= holders.size() == role.optimal();
            for (String holder : holders) {
                assertTrue(role.requirement().isMetBy(byId.get(holder)), seed + ": " + holder + " holds " + role.name()
                        + " but lacks " + role.requirement().missingFrom(byId.get(holder)).describe());
                assertTrue(team.rolesOf(holder).contains(role.name()), seed + ": holders and assignments agree");
            }
        }
        for (Assignment assignment : team.assignments()) {
            assertTrue(mission.allowsOnOneVehicle(assignment.roles()), seed + ": " + assignment + " breaks a colocation rule");
            optimal &= !assignment.isShared();
            for (String role : assignment.roles()) {
                assertTrue(team.holdersOf(role).contains(assignment.vehicle()), seed + ": assignments and holders agree");
            }
        }
        assertEquals(minimal, team.minimalMet(), seed + ": minimalMet");
        assertEquals(optimal, team.optimalReached(), seed + ": optimalReached");
    }
}
