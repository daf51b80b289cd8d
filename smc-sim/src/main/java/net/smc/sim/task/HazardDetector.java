package net.smc.sim.task;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import net.smc.sim.hardware.ChemicalSensor;
import net.smc.sim.hardware.Pose;
import net.smc.sim.hardware.RobotHardware;
import net.smc.sim.map.OccupancyGrid;
import net.smc.sim.map.Point;

/**
 * Watches the chemical sensor while it runs and raises {@code hazardDetected} once per hazard (by
 * its tag), the first time the hazard is sensed at or above the threshold, at the robot's position
 * by its odometry. The sensor gives no bearing, so that position is the estimate: the stronger the
 * threshold, the nearer the hazard's centre.
 *
 * <p>Told to {@link #inspect} a point, it drives there with a {@link Navigator} of its own on the
 * robot's map, keeping out of the hazards it has confirmed, and ends the inspection (the event
 * {@code inspected}) when the sensor reads the threshold, when it is there, or when no way is left.
 * Only the threshold keeps it out of the hazard it looks for: a threshold so high that it is read
 * only inside the hazard's radius of effect takes the robot in.
 */
public final class HazardDetector extends RobotTask implements HazardDetectorI, Handover {
    /** How close two points are to count as one suspect, metres. */
    private static final double SAME_POINT = 1.0;
    /** How far short of a suspected point the detector stops if its sensor has not read the threshold before, metres. */
    private static final double APPROACH = 0.8;
    /** The largest radius of the zone kept around a confirmed hazard while driving to another, metres. */
    private static final double CONFIRMED_ZONE = 1.0;

    private final Map<String, List<Object>> found = new LinkedHashMap<>();
    private final List<Point> queue = new ArrayList<>();
    private final Navigator navigator;
    private final OccupancyGrid map;
    private double threshold = 0.5;
    private Point inspecting;
    private int foundBefore;

    public HazardDetector(TaskContext context) {
        this(context.hardware(), context.map());
    }

    /** A detector that watches but cannot {@link #inspect} (no map to drive on). */
    public HazardDetector(RobotHardware hardware) {
        this(hardware, null);
    }

    public HazardDetector(RobotHardware hardware, OccupancyGrid map) {
        super(hardware);
        this.map = map;
        this.navigator = map == null ? null : new Navigator(hardware, map);
        if (navigator != null) {
            navigator.margin(0.2);
        }
    }

    @Override
    public void inspect(double x, double y) {
        StateValues.finite("HazardDetector inspect x", x);
        StateValues.finite("HazardDetector inspect y", y);
        if (navigator == null) {
            throw new IllegalStateException("HazardDetector of " + hardware.id() + " has no map to drive on; it cannot inspect");
        }
        if (near(x, y, inspecting) || queue.stream().anyMatch(p -> near(x, y, p)) || nearConfirmed(x, y)) {
            return;
        }
        queue.add(new Point(x, y));
    }

    @Override
    public void merge(net.smc.policy.api.ArrayValue cells) {
        java.util.Objects.requireNonNull(cells, "cells");
        if (map == null) {
            throw new IllegalStateException("HazardDetector of " + hardware.id() + " has no map to merge into");
        }
        Map<String, Object> state = map.toState();
        state.put("cells", cells.items());
        map.fillUnknown(OccupancyGrid.fromState(state));
    }

    @Override
    public boolean isInspecting() {
        return inspecting != null || !queue.isEmpty();
    }

    @Override
    public void inspected(double x, double y, boolean found) {
        raise("inspected", x, y, found);
    }

    private static boolean near(double x, double y, Point p) {
        return p != null && p.distanceTo(x, y) < SAME_POINT;
    }

    private boolean nearConfirmed(double x, double y) {
        for (List<Object> h : found.values()) {
            if (Math.hypot(((Number) h.get(2)).doubleValue() - x, ((Number) h.get(3)).doubleValue() - y) < SAME_POINT + 0.6) {
                return true;
            }
        }
        return false;
    }

    @Override
    protected boolean drives() {
        return navigator != null;
    }

    @Override
    public void threshold(double strength) {
        if (!(strength >= 0 && strength <= 1)) {
            throw new IllegalArgumentException("HazardDetector threshold " + strength + " must lie in 0..1");
        }
        threshold = strength;
    }

    @Override
    public List<List<Object>> hazards() {
        return List.copyOf(found.values());
    }

    @Override
    public void hazardDetected(String name, String uav, String kind, double x, double y) {
        raise("hazardDetected", name, uav, kind, x, y);
    }

    @Override
    protected void step(double time, double dt) {
        if (!hardware.has(RobotHardware.Device.CHEMICAL)) {
            return;
        }
        Pose pose = hardware.odometry().pose();
        boolean sensed = false;
        for (ChemicalSensor.Reading r : hardware.chemical().sense()) {
            if (r.strength() >= threshold) {
                sensed = true;
                if (!found.containsKey(r.tag())) {
                    found.put(r.tag(), List.of(r.tag(), r.kind(), pose.x(), pose.y()));
                    keepAway(pose);
                    hazardDetected("hazardDetected", hardware.id(), r.kind(), pose.x(), pose.y());
                }
            }
        }
        if (navigator != null) {
            drive(time, dt, pose, sensed);
        }
    }

    /** Works through the queue: the nearest point first, until the sensor reads the threshold or it is there. */
    private void drive(double time, double dt, Pose pose, boolean sensed) {
        if (inspecting == null) {
            queue.removeIf(p -> nearConfirmed(p.x(), p.y()));
        }
        if (inspecting == null && !queue.isEmpty()) {
            queue.sort(java.util.Comparator.comparingDouble(p -> p.distanceTo(pose.x(), pose.y())));
            inspecting = queue.remove(0);
            foundBefore = found.size();
            Point approach = approach(inspecting, pose);
            navigator.goTo(approach.x(), approach.y());
        }
        if (inspecting == null) {
            return;
        }
        if (found.size() > foundBefore || sensed && inspecting.distanceTo(pose.x(), pose.y()) < 2.5) {
            finish(true);
            return;
        }
        navigator.step(time, dt);
        if (!navigator.isMoving()) {
            finish(false);
        }
    }

    /**
     * After confirming a hazard while inspecting a point: keep out of a circle about that point
     * from now on, as large as leaves the robot, where it stands, outside it and the margin.
     */
    private void keepAway(Pose pose) {
        if (navigator == null || inspecting == null) {
            return;
        }
        double d = inspecting.distanceTo(pose.x(), pose.y());
        double radius = d - navigator.margin() - 0.25;
        if (radius > 0.1) {
            navigator.avoid(inspecting.x(), inspecting.y(), Math.min(radius, CONFIRMED_ZONE));
        }
    }

    /**
     * Where to drive to inspect a point: {@link #APPROACH} short of it on the robot's side (the
     * point itself is where the hazard's body may stand, a cell the planner keeps closed).
     */
    private Point approach(Point p, Pose pose) {
        double d = p.distanceTo(pose.x(), pose.y());
        if (d <= APPROACH) {
            return new Point(pose.x(), pose.y());
        }
        double f = APPROACH / d;
        return new Point(p.x() + (pose.x() - p.x()) * f, p.y() + (pose.y() - p.y()) * f);
    }

    private void finish(boolean sensed) {
        Point done = inspecting;
        inspecting = null;
        navigator.halt();
        inspected(done.x(), done.y(), sensed);
    }

    /**
     * {@code threshold}; {@code hazards}: the reports so far, each [tag, kind, x, y]; {@code queue}:
     * the points still to inspect, each [x, y].
     */
    @Override
    public Map<String, Object> exportState() {
        Map<String, Object> state = new LinkedHashMap<>();
        state.put("threshold", threshold);
        state.put("hazards", new ArrayList<>(found.values()));
        List<Object> points = new ArrayList<>();
        if (inspecting != null) {
            points.add(List.of(inspecting.x(), inspecting.y()));
        }
        queue.forEach(p -> points.add(List.of(p.x(), p.y())));
        state.put("queue", points);
        return state;
    }

    /** Takes over the threshold, the reports (those hazards are not reported again) and the points to inspect. */
    @Override
    public void importState(Map<String, ?> state) {
        if (StateValues.has(state, "threshold")) {
            threshold(StateValues.number("HazardDetector", state, "threshold"));
        }
        if (StateValues.has(state, "hazards")) {
            for (Object o : StateValues.list("HazardDetector", state, "hazards")) {
                if (!(o instanceof List<?> h) || h.size() != 4 || !(h.get(0) instanceof String tag)
                        || !(h.get(1) instanceof String kind) || !(h.get(2) instanceof Number x)
                        || !(h.get(3) instanceof Number y)) {
                    throw new IllegalArgumentException("HazardDetector state: each of 'hazards' must be"
                            + " [tag, kind, x, y], got " + o);
                }
                found.putIfAbsent(tag, List.of(tag, kind, x.doubleValue(), y.doubleValue()));
            }
        }
        if (StateValues.has(state, "queue") && navigator != null) {
            for (Object o : StateValues.list("HazardDetector", state, "queue")) {
                if (!(o instanceof List<?> p) || p.size() != 2 || !(p.get(0) instanceof Number x)
                        || !(p.get(1) instanceof Number y)) {
                    throw new IllegalArgumentException("HazardDetector state: each of 'queue' must be [x, y], got " + o);
                }
                inspect(x.doubleValue(), y.doubleValue());
            }
        }
    }
}
