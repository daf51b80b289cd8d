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
 * robot's map (with the Explorer's clearance, which fits doorways), keeping out of the hazards it has confirmed, and ends the inspection (the event
 * {@code inspected}) when the sensor reads the threshold or when the suspect is given up. A suspect
 * is given up only when it has been looked at from {@link #SIDES} sides (each {@link #APPROACH}
 * from it) without the sensor reading the threshold, or after {@link #ATTEMPTS} tries: a try that
 * finds no way there is repeated after {@link #RETRY_AFTER} seconds (the map grows meanwhile), from
 * the next side. Only the threshold keeps it out of the hazard it looks for: a threshold so high that it is read
 * only inside the hazard's radius of effect takes the robot in. Told where a failed teammate's body
 * lies ({@link #pushAside}), its Navigator goes around the body or pushes it aside.
 */
public final class HazardDetector extends RobotTask implements HazardDetectorI, Handover {
    /** How close two points are to count as one suspect, metres. */
    private static final double SAME_POINT = 1.0;
    /** How far short of a suspected point the detector stops if its sensor has not read the threshold before, metres. */
    private static final double APPROACH = 0.8;
    /** The largest radius of the zone kept around a confirmed hazard while driving to another, metres. */
    private static final double CONFIRMED_ZONE = 1.0;
    /** The sides from which a suspect is looked at before it is taken to be absent. */
    static final int SIDES = 4;
    /** How many tries a suspect gets in all (arrivals and blocked drives). */
    static final int ATTEMPTS = 8;
    /** Seconds after a blocked try before the suspect is tried again. */
    static final double RETRY_AFTER = 3;
    /**
     * How near the robot a suspect must lie for a hazard the sensor reads at the threshold to be
     * taken for that suspect's, metres: the threshold is read about a metre out, and the camera's
     * estimate of where a hazard lies is off by some tenths.
     */
    static final double REACH = 2.5;
    /** How close to the approach point the robot must stand to count as having looked from there, metres. */
    private static final double THERE = 0.35;

    /**
     * A point to inspect: {@code bearing} is the direction from the point of the first side to look
     * from (NaN until the first try), {@code tries} the tries so far, {@code looked} the sides
     * reached without reading the threshold, {@code notBefore} the time before which it waits.
     */
    private record Suspect(Point at, double bearing, int tries, int looked, double notBefore) {
        Point approach() {
            double a = bearing + tries * 2 * Math.PI / SIDES;
            return new Point(at.x() + Math.cos(a) * APPROACH, at.y() + Math.sin(a) * APPROACH);
        }
    }

    private final Map<String, List<Object>> found = new LinkedHashMap<>();
    private final List<Suspect> queue = new ArrayList<>();
    private final Navigator navigator;
    private final OccupancyGrid map;
    private double threshold = 0.5;
    private Suspect inspecting;
    private Point approach;
    /** Whether a hazard sensed since the inspection began was taken to be the one inspected. */
    private boolean targetSensed;

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
        this.navigator = map == null ? null : new Navigator(hardware, map, Explorer.CLEARANCE);
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
        if (inspecting != null && near(x, y, inspecting.at()) || queue.stream().anyMatch(p -> near(x, y, p.at()))
                || nearConfirmed(x, y)) {
            return;
        }
        queue.add(new Suspect(new Point(x, y), Double.NaN, 0, 0, Double.NEGATIVE_INFINITY));
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

    /** The navigator it drives with, or null when it has no map (for tests: the zones it keeps out of). */
    Navigator navigator() {
        return navigator;
    }

    @Override
    public void pushAside(double x, double y) {
        StateValues.finite("HazardDetector pushAside x", x);
        StateValues.finite("HazardDetector pushAside y", y);
        if (navigator != null) {   // one without a map does not drive, so no body is in its way
            navigator.pushAside(x, y);
        }
    }

    /** The failed teammates' bodies it was told of (for tests). */
    List<Point> bodies() {
        return navigator == null ? List.of() : navigator.bodies();
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
                    attribute(pose);
                    hazardDetected("hazardDetected", hardware.id(), r.kind(), pose.x(), pose.y());
                }
            }
        }
        if (navigator != null) {
            drive(time, dt, pose, sensed);
        }
    }

    /**
     * Works through the queue: of the points whose wait is over, the least tried and then the
     * nearest first, until the sensor reads
     * the threshold, or the point has been looked at from every side, or its tries are used up.
     */
    private void drive(double time, double dt, Pose pose, boolean sensed) {
        if (inspecting == null) {
            queue.removeIf(p -> nearConfirmed(p.at().x(), p.at().y()));
            Suspect next = null;
            for (Suspect p : queue) {
                if (p.notBefore() <= time && (next == null || p.tries() < next.tries() || p.tries() == next.tries()
                        && p.at().distanceTo(pose.x(), pose.y()) < next.at().distanceTo(pose.x(), pose.y()))) {
                    next = p;
                }
            }
            if (next == null) {
                return;
            }
            queue.remove(next);
            if (Double.isNaN(next.bearing())) {
                next = new Suspect(next.at(), Math.atan2(pose.y() - next.at().y(), pose.x() - next.at().x()), 0, 0, time);
            }
            inspecting = next;
            targetSensed = false;
            approach = next.tries() == 0 && next.at().distanceTo(pose.x(), pose.y()) <= APPROACH
                    ? new Point(pose.x(), pose.y()) : next.approach();
            navigator.goTo(approach.x(), approach.y());
        }
        if (targetSensed || sensed && inspecting.at().distanceTo(pose.x(), pose.y()) < REACH) {
            finish(true);
            return;
        }
        navigator.step(time, dt);
        if (!navigator.isMoving()) {
            boolean there = approach.distanceTo(pose.x(), pose.y()) <= THERE;
            Suspect s = inspecting;
            Suspect again = new Suspect(s.at(), s.bearing(), s.tries() + 1, s.looked() + (there ? 1 : 0),
                    there ? time : time + RETRY_AFTER);
            if (again.looked() >= SIDES || again.tries() >= ATTEMPTS) {
                finish(false);
            } else {
                inspecting = null;
                navigator.halt();
                queue.add(again);
            }
        }
    }

    /**
     * Which suspect a hazard first sensed where the robot stands is: the one, of the point being
     * inspected and those queued, nearest the robot and within {@link #REACH} of it. The sensor
     * gives no bearing, so a hazard sensed on the way to a point farther off is not that point's
     * hazard: before, any new hazard ended the inspection under way as confirmed and closed a
     * zone round the point inspected, so a detector that passed one suspect on its way to another
     * took the other for confirmed and could never reach it again. A queued suspect so sensed is
     * done with (it is not inspected again); a hazard no suspect explains is reported only.
     */
    private void attribute(Pose pose) {
        if (navigator == null) {
            return;
        }
        Suspect nearest = null;
        double best = REACH;
        List<Suspect> candidates = new ArrayList<>(queue);
        if (inspecting != null) {
            candidates.add(0, inspecting);
        }
        for (Suspect s : candidates) {
            double d = s.at().distanceTo(pose.x(), pose.y());
            if (d < best) {
                best = d;
                nearest = s;
            }
        }
        if (nearest == null) {
            return;
        }
        keepAway(pose, nearest.at());
        if (nearest == inspecting) {
            targetSensed = true;
        } else {
            queue.remove(nearest);
        }
    }

    /**
     * After confirming the hazard of a suspected point: keep out of a circle about that point from
     * now on, as large as leaves the robot, where it stands, outside it and the margin.
     */
    private void keepAway(Pose pose, Point p) {
        double d = p.distanceTo(pose.x(), pose.y());
        double radius = d - navigator.margin() - 0.25;
        if (radius > 0.1) {
            navigator.avoid(p.x(), p.y(), Math.min(radius, CONFIRMED_ZONE));
        }
    }

    private void finish(boolean sensed) {
        Point done = inspecting.at();
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
            points.add(List.of(inspecting.at().x(), inspecting.at().y()));
        }
        queue.forEach(p -> points.add(List.of(p.at().x(), p.at().y())));
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
