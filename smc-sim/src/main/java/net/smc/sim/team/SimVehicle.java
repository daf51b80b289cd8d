package net.smc.sim.team;

import java.util.List;
import java.util.Set;
import java.util.TreeSet;

import net.smc.core.capability.CapabilityDescription;
import net.smc.core.capability.TaskDescription;

/**
 * A vehicle of a simulated team: its id, what it can do, and how it enters the team.
 *
 * @param id        the vehicle id (a valid PonderTalk name: letters, digits, {@code _})
 * @param resources its resources ({@code motion}, {@code video} ...)
 * @param tasks     the names of its tasks ({@code Explorer} ...)
 * @param commander whether it is the acting commander from the start
 * @param rogue     whether its credential comes from a foreign authority: it must get nowhere
 */
public record SimVehicle(String id, Set<String> resources, Set<String> tasks, boolean commander, boolean rogue) {

    public SimVehicle {
        resources = Set.copyOf(resources);
        tasks = Set.copyOf(tasks);
    }

    /** Its full capability description (tasks without operations: only names are matched). */
    public CapabilityDescription description() {
        return CapabilityDescription.of(id, new TreeSet<>(resources),
                tasks.stream().sorted().map(TaskDescription::empty).toList());
    }

    public SimVehicle asRogue() {
        return new SimVehicle(id, resources, tasks, commander, true);
    }

    public SimVehicle asCommander() {
        return new SimVehicle(id, resources, tasks, true, rogue);
    }

    // The vehicle kinds of the reconnaissance mission (missions/reconnaissance.class.xml).

    /** Able to command (and so to back up the commander) and to aggregate. */
    public static SimVehicle command(String id) {
        return new SimVehicle(id, Set.of("communication"), Set.of("Aggregator"), false, false);
    }

    /** A surveyor able to carry the hazard-detector and relay roles too. */
    public static SimVehicle surveyor(String id) {
        return new SimVehicle(id, Set.of("motion", "video", "chemical", "communication"),
                Set.of("Explorer", "HazardDetector", "Relay"), false, false);
    }

    public static SimVehicle aggregator(String id) {
        return new SimVehicle(id, Set.of("communication"), Set.of("Aggregator"), false, false);
    }

    public static SimVehicle detector(String id) {
        return new SimVehicle(id, Set.of("motion", "chemical"), Set.of("HazardDetector"), false, false);
    }

    public static SimVehicle relay(String id) {
        return new SimVehicle(id, Set.of("motion", "communication"), Set.of("Relay"), false, false);
    }

    /**
     * A reconnaissance team: the commander, then {@code surveyors}, {@code aggregators},
     * {@code detectors} and {@code relays} vehicles, named {@code cdr}, {@code s1}, {@code a1}, {@code d1}, {@code r1} ...
     */
    public static List<SimVehicle> reconnaissance(int surveyors, int aggregators, int detectors, int relays) {
        List<SimVehicle> team = new java.util.ArrayList<>();
        team.add(command("cdr").asCommander());
        for (int i = 1; i <= surveyors; i++) {
            team.add(surveyor("s" + i));
        }
        for (int i = 1; i <= aggregators; i++) {
            team.add(aggregator("a" + i));
        }
        for (int i = 1; i <= detectors; i++) {
            team.add(detector("d" + i));
        }
        for (int i = 1; i <= relays; i++) {
            team.add(relay("r" + i));
        }
        return team;
    }
}
