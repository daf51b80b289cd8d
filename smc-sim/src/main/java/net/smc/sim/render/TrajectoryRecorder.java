package net.smc.sim.render;

import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import net.smc.sim.robot.SimRobot;
import net.smc.sim.world.SimWorld;
import net.smc.sim.world.WorldStepListener;

/**
 * Records where each robot of a world went: its position every {@code every} steps (and at the
 * first step it is seen, and the step it is disabled), and where and why each robot was disabled.
 * Add it to the world with {@link SimWorld#addListener}; the painter draws its paths.
 */
public final class TrajectoryRecorder implements WorldStepListener {
    private final int every;
    private final Map<String, List<Point>> paths = new LinkedHashMap<>();
    private final Map<String, Stop> stops = new LinkedHashMap<>();

    /** A point of a path: mission time in seconds, position in metres. */
    public record Point(double time, double x, double y) {
    }

    /** Where robot {@code robotId} was disabled, when, and by what ({@code hazard:ID}, {@code battery}, ...). */
    public record Stop(String robotId, double time, double x, double y, String cause) {
    }

    /** Samples every {@code every} steps (1 or more). */
    public TrajectoryRecorder(int every) {
        if (every < 1) {
            throw new IllegalArgumentException("sampling every " + every + " steps is out of range; it must be 1 or more");
        }
        this.every = every;
    }

    @Override
    public void stepped(SimWorld world) {
        boolean due = world.steps() % every == 0;
        for (SimRobot robot : world.robots()) {
            List<Point> path = paths.get(robot.id());
            if (path == null) {
                path = new ArrayList<>();
                paths.put(robot.id(), path);
                path.add(new Point(world.time(), robot.x(), robot.y()));
            } else if (due && !robot.disabled()) {
                path.add(new Point(world.time(), robot.x(), robot.y()));
            }
        }
    }

    @Override
    public void disabled(SimWorld world, SimRobot robot, String cause) {
        paths.computeIfAbsent(robot.id(), k -> new ArrayList<>()).add(new Point(world.time(), robot.x(), robot.y()));
        stops.putIfAbsent(robot.id(), new Stop(robot.id(), world.time(), robot.x(), robot.y(), cause));
    }

    /** The robots seen so far, in the order first seen. */
    public List<String> robotIds() {
        return List.copyOf(paths.keySet());
    }

    /** Robot {@code robotId}'s path so far (empty if never seen); a read-only view. */
    public List<Point> path(String robotId) {
        List<Point> path = paths.get(robotId);
        return path == null ? List.of() : Collections.unmodifiableList(path);
    }

    /** Where the robots were disabled, in the order it happened. */
    public List<Stop> stops() {
        return List.copyOf(stops.values());
    }

    /** The length of robot {@code robotId}'s recorded path, m. */
    public double length(String robotId) {
        List<Point> path = path(robotId);
        double sum = 0;
        for (int i = 1; i < path.size(); i++) {
            sum += Math.hypot(path.get(i).x() - path.get(i - 1).x(), path.get(i).y() - path.get(i - 1).y());
        }
        return sum;
    }
}
