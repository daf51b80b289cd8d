package net.smc.core.team;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;

/**
 * Who holds which roles of a mission, as {@link TeamPlanner} computed it for a set of vehicles.
 * Every collection is immutable and ordered (vehicles by id, roles in the mission's order), so two
 * plans of the same input are equal and print the same.
 *
 * @param assignments    the vehicles that hold roles, by id
 * @param holders        each role of the mission (all of them, in the mission's order) to the
 *                       vehicles that hold it, by id
 * @param spare          the vehicles that hold no role, by id
 * @param minimalMet     whether every role has at least its minimal number of holders: the mission may start
 * @param optimalReached whether every role has its reasonably-optimal number of holders and no
 *                       secondary role rides on another role's vehicle
 */
public record TeamConfiguration(List<Assignment> assignments, Map<String, List<String>> holders, List<String> spare,
                                boolean minimalMet, boolean optimalReached) {

    public TeamConfiguration {
        assignments = List.copyOf(assignments);
        Map<String, List<String>> copy = new LinkedHashMap<>();
        holders.forEach((role, vehicles) -> copy.put(role, List.copyOf(vehicles)));
        holders = Collections.unmodifiableMap(copy);
        spare = List.copyOf(spare);
    }

    /** The roles {@code vehicle} holds (empty for a spare or unknown vehicle). */
    public List<String> rolesOf(String vehicle) {
        return assignments.stream().filter(a -> a.vehicle().equals(vehicle)).findFirst()
                .map(Assignment::roles).orElse(List.of());
    }

    /** The vehicles holding {@code role} (empty for an unknown role). */
    public List<String> holdersOf(String role) {
        return holders.getOrDefault(role, List.of());
    }

    /** The vehicle holding the commander role, if any. */
    public Optional<String> commander() {
        return holdersOf(net.smc.core.mission.Mission.COMMANDER).stream().findFirst();
    }

    /** The vehicle → roles view, by vehicle id. */
    public Map<String, List<String>> rolesByVehicle() {
        Map<String, List<String>> byVehicle = new LinkedHashMap<>();
        assignments.forEach(a -> byVehicle.put(a.vehicle(), a.roles()));
        return Collections.unmodifiableMap(byVehicle);
    }
}
