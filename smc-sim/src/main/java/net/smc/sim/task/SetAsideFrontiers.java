package net.smc.sim.task;

import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.Map;

import net.smc.sim.map.OccupancyGrid;

/**
 * The frontiers an {@link Explorer} gave up on: each with the time until which it, and the frontier
 * cells within {@link #RADIUS} of it, are not chosen, and how often it was given up on. The first
 * time a frontier is set aside for {@link #FIRST_SECONDS}, each further time twice as long as the
 * time before, up to {@link #MAX_SECONDS}.
 */
final class SetAsideFrontiers {
    /** How long a frontier given up on is set aside the first time, s. */
    static final double FIRST_SECONDS = 20;
    /** The longest a frontier is set aside, s. */
    static final double MAX_SECONDS = 160;
    /** Frontier cells within this of one given up on are set aside with it, m: they share its unknown region. */
    static final double RADIUS = 0.5;

    private final OccupancyGrid map;
    private final Map<Integer, Double> until = new LinkedHashMap<>();
    private final Map<Integer, Integer> failures = new HashMap<>();

    SetAsideFrontiers(OccupancyGrid map) {
        this.map = map;
    }

    /** The frontier {@code cell} (column + row x columns) was given up on at {@code time}. */
    void add(int cell, double time) {
        int n = failures.merge(cell, 1, Integer::sum);
        until.put(cell, time + Math.min(MAX_SECONDS, FIRST_SECONDS * Math.pow(2, n - 1)));
    }

    /** Whether the cell at {@code col}, {@code row} is set aside at {@code time}. */
    boolean holds(int col, int row, double time) {
        until.values().removeIf(t -> t <= time);
        double reach = RADIUS / map.resolution();
        for (int cell : until.keySet()) {
            if (Math.hypot(cell % map.cols() - col, cell / map.cols() - row) <= reach + 1e-9) {
                return true;
            }
        }
        return false;
    }
}
