package net.smc.sim.task;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import net.smc.policy.api.ArrayValue;
import net.smc.sim.hardware.RobotHardware;
import net.smc.sim.map.OccupancyGrid;

/**
 * Merges what the team learns into one picture: the robots' maps ({@link #merge(OccupancyGrid)},
 * into this robot's map) and hazard reports ({@link #report}), de-duplicated: a report within the
 * merge radius of a known hazard of the same kind refines that hazard's position (the mean of its
 * reports) rather than adding one. It drives nothing, so it needs no control loop.
 */
public final class Aggregator extends RobotTask implements AggregatorI, Handover {
    private final OccupancyGrid map;
    private final List<Hazard> hazards = new ArrayList<>();
    private double mergeRadius = 1.0;

    private static final class Hazard {
        final String kind;
        double sumX;
        double sumY;
        int reports;

        Hazard(String kind) {
            this.kind = kind;
        }

        double x() {
            return sumX / reports;
        }

        double y() {
            return sumY / reports;
        }
    }

    public Aggregator(TaskContext context) {
        this(context.hardware(), context.map());
    }

    public Aggregator(RobotHardware hardware, OccupancyGrid map) {
        super(hardware);
        this.map = Objects.requireNonNull(map, "map");
    }

    /** Merges a robot's map into the picture ({@link OccupancyGrid#merge}). */
    public void merge(OccupancyGrid other) {
        map.merge(other);
    }

    @Override
    public void merge(ArrayValue cells) {
        java.util.Objects.requireNonNull(cells, "cells");
        Map<String, Object> state = map.toState();
        state.put("cells", cells.items());
        merge(OccupancyGrid.fromState(state));
    }

    public OccupancyGrid map() {
        return map;
    }

    @Override
    public void report(String kind, double x, double y) {
        if (kind == null || kind.isBlank()) {
            throw new IllegalArgumentException("Aggregator report: a hazard's kind must not be blank");
        }
        StateValues.finite("Aggregator report x", x);
        StateValues.finite("Aggregator report y", y);
        Hazard same = null;
        double nearest = Double.POSITIVE_INFINITY;
        for (Hazard h : hazards) {
            double d = Math.hypot(h.x() - x, h.y() - y);
            if (h.kind.equals(kind) && d <= mergeRadius && d < nearest) {
                same = h;
                nearest = d;
            }
        }
        boolean added = same == null;
        if (added) {
            same = new Hazard(kind);
            hazards.add(same);
        }
        same.sumX += x;
        same.sumY += y;
        same.reports++;
        if (added) {
            hazardAdded(kind, x, y);
        }
    }

    @Override
    public List<List<Object>> hazards() {
        List<List<Object>> all = new ArrayList<>();
        for (Hazard h : hazards) {
            all.add(List.of(h.kind, h.x(), h.y(), h.reports));
        }
        return all;
    }

    @Override
    public double exploredFraction() {
        return map.exploredFraction();
    }

    @Override
    public void mergeRadius(double metres) {
        if (!(metres >= 0) || !Double.isFinite(metres)) {
            throw new IllegalArgumentException("Aggregator merge radius " + metres + " must be a finite number of metres, 0 or more");
        }
        mergeRadius = metres;
    }

    @Override
    public void hazardAdded(String kind, double x, double y) {
        raise("hazardAdded", kind, x, y);
    }

    @Override
    protected void onStart() {
        // Nothing to drive: reports and maps arrive through its operations.
    }

    @Override
    protected void onStop() {
        // No control loop was registered.
    }

    @Override
    protected void step(double time, double dt) {
        // Never registered; see onStart.
    }

    /** {@code hazards}: [kind, x, y, reports] each; {@code map}: the merged grid. */
    @Override
    public Map<String, Object> exportState() {
        Map<String, Object> state = new LinkedHashMap<>();
        List<Object> list = new ArrayList<>();
        for (Hazard h : hazards) {
            list.add(List.of(h.kind, h.x(), h.y(), h.reports));
        }
        state.put("hazards", list);
        state.put("mergeRadius", mergeRadius);
        state.put("map", map.toState());
        return state;
    }

    @Override
    public void importState(Map<String, ?> state) {
        if (StateValues.has(state, "mergeRadius")) {
            mergeRadius(StateValues.number("Aggregator", state, "mergeRadius"));
        }
        if (StateValues.has(state, "map")) {
            map.merge(OccupancyGrid.fromState(StateValues.map("Aggregator", state, "map")));
        }
        if (StateValues.has(state, "hazards")) {
            for (Object o : StateValues.list("Aggregator", state, "hazards")) {
                if (!(o instanceof List<?> h) || h.size() != 4 || !(h.get(0) instanceof String kind)
                        || !(h.get(1) instanceof Number x) || !(h.get(2) instanceof Number y)
                        || !(h.get(3) instanceof Number n) || n.intValue() < 1) {
                    throw new IllegalArgumentException("Aggregator state: each of 'hazards' must be"
                            + " [kind, x, y, reports], got " + o);
                }
                Hazard hazard = new Hazard(kind);
                hazard.reports = n.intValue();
                hazard.sumX = x.doubleValue() * hazard.reports;
                hazard.sumY = y.doubleValue() * hazard.reports;
                hazards.add(hazard);
            }
        }
    }
}
