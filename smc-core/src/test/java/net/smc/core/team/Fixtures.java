package net.smc.core.team;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Random;
import java.util.Set;
import java.util.TreeSet;
import net.smc.core.capability.CapabilityRequirement;
import net.smc.core.capability.CapabilitySummary;
import net.smc.core.mission.Colocation;
import net.smc.core.mission.Mission;
import net.smc.core.mission.MissionRole;

/** Missions and vehicles for the planner's tests, built in code. */
final class Fixtures {
    private Fixtures() {
    }

    static MissionRole role(String name, int minimal, int optimal, List<String> manages, String primary,
                            Set<String> resources, Set<String> tasks) {
        return new MissionRole(name, minimal, optimal, manages, CapabilityRequirement.of(resources, tasks),
                Optional.ofNullable(primary), List.of("policy:/roles/" + name + "/mission"), List.of());
    }

    /** The reconnaissance of section II-A, as missions/reconnaissance.*.xml give it. */
    static Mission reconnaissance() {
        return new Mission("Reconnaissance", "test", List.of(
                role("commander", 1, 1, List.of("surveyor", "aggregator"), null, Set.of("communication"), Set.of()),
                role("surveyor", 2, 2, List.of("hdetector", "relay"), null, Set.of("motion", "video"), Set.of("Explorer")),
                role("aggregator", 1, 1, List.of(), null, Set.of("communication"), Set.of("Aggregator")),
                role("hdetector", 2, 2, List.of(), "surveyor", Set.of("motion", "chemical"), Set.of("HazardDetector")),
                role("relay", 2, 2, List.of(), "surveyor", Set.of("motion", "communication"), Set.of("Relay"))),
                new Colocation(List.of(new Colocation.Parallel("relay", List.of("surveyor", "hdetector"))),
                        List.of(new Colocation.Exclusive(List.of("surveyor", "hdetector")))),
                Map.of());
    }

    static CapabilitySummary vehicle(String id, Set<String> resources, Set<String> tasks) {
        return new CapabilitySummary(id, new TreeSet<>(resources), new TreeSet<>(tasks));
    }

    static CapabilitySummary commanderVehicle(String id) {
        return vehicle(id, Set.of("communication"), Set.of());
    }

    static CapabilitySummary aggregatorVehicle(String id) {
        return vehicle(id, Set.of("communication"), Set.of("Aggregator"));
    }

    /** A vehicle that can survey, detect hazards and relay. */
    static CapabilitySummary allRounder(String id) {
        return vehicle(id, Set.of("motion", "video", "chemical", "communication"), Set.of("Explorer", "HazardDetector", "Relay"));
    }

    static CapabilitySummary relayVehicle(String id) {
        return vehicle(id, Set.of("motion", "communication"), Set.of("Relay"));
    }

    static CapabilitySummary detectorVehicle(String id) {
        return vehicle(id, Set.of("motion", "chemical"), Set.of("HazardDetector"));
    }

    static final List<String> RESOURCES = List.of("a", "b", "c", "d");
    static final List<String> TASKS = List.of("T1", "T2");

    /**
     * A random small mission: a commander and 1 to {@code maxOthers} roles in a random tree, some
     * secondary to their manager, random colocation rules, cardinalities and requirements.
     */
    static Mission randomMission(Random random, int maxOthers) {
        int others = 1 + random.nextInt(maxOthers);
        List<String> names = new ArrayList<>(List.of("commander"));
        for (int i = 0; i < others; i++) {
            names.add("r" + i);
        }
        String[] manager = new String[names.size()];
        boolean[] secondary = new boolean[names.size()];
        List<Colocation.Parallel> parallel = new ArrayList<>();
        List<Colocation.Exclusive> exclusive = new ArrayList<>();
        for (int i = 1; i < names.size(); i++) {
            int m = random.nextInt(i);
            manager[i] = names.get(m);
            if (!secondary[m] && random.nextInt(5) < 2) {
                secondary[i] = true;
                if (random.nextBoolean()) {
                    parallel.add(new Colocation.Parallel(names.get(i), List.of(manager[i])));
                } else {
                    exclusive.add(new Colocation.Exclusive(List.of(names.get(i), manager[i])));
                }
            }
        }
        for (int i = 1; i < names.size(); i++) {
            for (int j = i + 1; j < names.size(); j++) {
                if (random.nextInt(4) == 0) {
                    parallel.add(new Colocation.Parallel(names.get(i), List.of(names.get(j))));
                }
            }
        }
        List<MissionRole> roles = new ArrayList<>();
        for (int i = 0; i < names.size(); i++) {
            List<String> manages = new ArrayList<>();
            for (int j = 1; j < names.size(); j++) {
                if (names.get(i).equals(manager[j])) {
                    manages.add(names.get(j));
                }
            }
            int minimal = i == 0 ? 1 : random.nextInt(3);
            int optimal = i == 0 ? 1 : Math.max(1, minimal + random.nextInt(3));
            roles.add(role(names.get(i), minimal, optimal, manages, secondary[i] ? manager[i] : null,
                    subset(random, RESOURCES, 30), subset(random, TASKS, 25)));
        }
        return new Mission("Random", "random", roles, new Colocation(parallel, exclusive), Map.of());
    }

    /** A random fleet of {@code n} vehicles with ids in random order. */
    static List<CapabilitySummary> randomVehicles(Random random, int n) {
        List<CapabilitySummary> vehicles = new ArrayList<>();
        for (int v = 0; v < n; v++) {
            vehicles.add(vehicle(String.format("v%03d", v), subset(random, RESOURCES, 60), subset(random, TASKS, 60)));
        }
        java.util.Collections.shuffle(vehicles, random);
        return vehicles;
    }

    /** Each of {@code names} with probability {@code percent}/100. */
    private static Set<String> subset(Random random, List<String> names, int percent) {
        Set<String> chosen = new TreeSet<>();
        for (String name : names) {
            if (random.nextInt(100) < percent) {
                chosen.add(name);
            }
        }
        return chosen;
    }
}
