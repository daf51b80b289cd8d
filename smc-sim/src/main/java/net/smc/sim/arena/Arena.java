package net.smc.sim.arena;

import java.util.List;
import java.util.Optional;

/**
 * An arena as its world file describes it: a fenced rectangle {@code [0, width] x [0, height]}
 * holding walls, doors, obstacles, hazards, the soldier, fixed radio stations and the robots'
 * start positions. Immutable; {@link ArenaReader} makes one from a file, {@link net.smc.sim.world.SimWorld} builds
 * the physical world from it. Lengths in metres, angles in radians (files write degrees).
 *
 * @param name     the arena's name
 * @param width    extent along x, m
 * @param height   extent along y, m
 * @param walls    straight walls (the fence around the arena is implied, not listed)
 * @param doors    doorways: open ones are markers the camera sees, closed ones block like walls
 * @param boxes    rectangular obstacles
 * @param cylinders round obstacles
 * @param hazards  hazards (the paper's yellow cylinder), each with a radius of effect
 * @param targets  tagged objects to find (the wounded soldier)
 * @param stations fixed radio nodes without a body (the commander's laptop, a wearable computer)
 * @param starts   start poses, in file order
 */
public record Arena(String name, double width, double height, List<Wall> walls, List<Door> doors,
                    List<Box> boxes, List<Cylinder> cylinders, List<Hazard> hazards, List<Target> targets,
                    List<Station> stations, List<Start> starts) {

    public Arena {
        walls = List.copyOf(walls);
        doors = List.copyOf(doors);
        boxes = List.copyOf(boxes);
        cylinders = List.copyOf(cylinders);
        hazards = List.copyOf(hazards);
        targets = List.copyOf(targets);
        stations = List.copyOf(stations);
        starts = List.copyOf(starts);
    }

    /** The start position called {@code id}. */
    public Optional<Start> start(String id) {
        return starts.stream().filter(s -> s.id().equals(id)).findFirst();
    }

    /** The hazard called {@code id}. */
    public Optional<Hazard> hazard(String id) {
        return hazards.stream().filter(h -> h.id().equals(id)).findFirst();
    }

    /** A wall from (x1, y1) to (x2, y2), {@code thickness} wide, centred on that segment. */
    public record Wall(double x1, double y1, double x2, double y2, double thickness) {
        public double length() {
            return Math.hypot(x2 - x1, y2 - y1);
        }
    }

    /** A doorway from (x1, y1) to (x2, y2); a closed door is a wall {@code thickness} wide. */
    public record Door(String id, double x1, double y1, double x2, double y2, double thickness, boolean open) {
    }

    /** A rectangular obstacle centred at (x, y), turned by {@code angle}. */
    public record Box(String id, double x, double y, double width, double height, double angle) {
    }

    /** A round obstacle. */
    public record Cylinder(String id, double x, double y, double radius) {
    }

    /**
     * A hazard: a solid cylinder of {@code radius} (0 for none: a spill) whose substance reaches
     * {@code effect} metres from its centre.
     *
     * @param disables whether a robot whose centre comes within {@code effect} loses its drive and
     *                 radio (the paper's surveyor, stopped by the yellow cylinder)
     */
    public record Hazard(String id, String kind, double x, double y, double radius, double effect, boolean disables) {
    }

    /** A tagged object to find, e.g. the wounded soldier ({@code kind} {@code soldier}). */
    public record Target(String id, String kind, double x, double y, double radius) {
    }

    /** A fixed radio node at (x, y), with no body. */
    public record Station(String id, double x, double y) {
    }

    /** A start pose for a robot. */
    public record Start(String id, double x, double y, double heading) {
    }
}
