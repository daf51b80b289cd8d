package net.smc.sim.scenario;

import java.util.Objects;

import net.smc.sim.arena.Arena;
import net.smc.sim.map.OccupancyGrid;

/**
 * How much of an arena's free floor a map knows. The free floor is the cells of the map's grid
 * whose centre lies more than {@link #CLEARANCE} from every wall, closed door, obstacle, hazard's
 * body and the fence: cells a robot's sensors can see into. A map covers such a cell when it knows
 * it (free or occupied).
 */
public final class FloorCoverage {
    /** How far a cell's centre must be from anything solid to count as free floor, metres. */
    public static final double CLEARANCE = 0.2;

    private final boolean[] floor;
    private final int cols;
    private final int rows;
    private final int floorCells;

    /** The free floor of {@code arena} on the grid of {@code like} (its origin, resolution and size). */
    public FloorCoverage(Arena arena, OccupancyGrid like) {
        Objects.requireNonNull(arena, "arena");
        this.cols = like.cols();
        this.rows = like.rows();
        this.floor = new boolean[cols * rows];
        int count = 0;
        for (int r = 0; r < rows; r++) {
            for (int c = 0; c < cols; c++) {
                var p = like.centre(c, r);
                if (clear(arena, p.x(), p.y())) {
                    floor[c + r * cols] = true;
                    count++;
                }
            }
        }
        this.floorCells = count;
    }

    /** How many cells are free floor. */
    public int floorCells() {
        return floorCells;
    }

    /** Whether the cell is free floor. */
    public boolean isFloor(int col, int row) {
        return col >= 0 && row >= 0 && col < cols && row < rows && floor[col + row * cols];
    }

    /**
     * The share of the free floor that {@code map} knows, 0..1.
     *
     * @throws IllegalArgumentException when the map's grid is not the one this was made for
     */
    public double of(OccupancyGrid map) {
        if (map.cols() != cols || map.rows() != rows) {
            throw new IllegalArgumentException("map " + map.describe() + " is not the grid of this coverage (" + cols + "x"
                    + rows + " cells)");
        }
        int known = 0;
        for (int r = 0; r < rows; r++) {
            for (int c = 0; c < cols; c++) {
                if (floor[c + r * cols] && map.isKnown(c, r)) {
                    known++;
                }
            }
        }
        return floorCells == 0 ? 1 : (double) known / floorCells;
    }

    private static boolean clear(Arena arena, double x, double y) {
        if (x < CLEARANCE || y < CLEARANCE || x > arena.width() - CLEARANCE || y > arena.height() - CLEARANCE) {
            return false;
        }
        for (Arena.Wall w : arena.walls()) {
            if (segment(x, y, w.x1(), w.y1(), w.x2(), w.y2()) <= w.thickness() / 2 + CLEARANCE) {
                return false;
            }
        }
        for (Arena.Door d : arena.doors()) {
            if (!d.open() && segment(x, y, d.x1(), d.y1(), d.x2(), d.y2()) <= d.thickness() / 2 + CLEARANCE) {
                return false;
            }
        }
        for (Arena.Cylinder c : arena.cylinders()) {
            if (Math.hypot(x - c.x(), y - c.y()) <= c.radius() + CLEARANCE) {
                return false;
            }
        }
        for (Arena.Hazard h : arena.hazards()) {
            if (h.radius() > 0 && Math.hypot(x - h.x(), y - h.y()) <= h.radius() + CLEARANCE) {
                return false;
            }
        }
        for (Arena.Box b : arena.boxes()) {
            double cos = Math.cos(-b.angle());
            double sin = Math.sin(-b.angle());
            double lx = (x - b.x()) * cos - (y - b.y()) * sin;
            double ly = (x - b.x()) * sin + (y - b.y()) * cos;
            double dx = Math.max(0, Math.abs(lx) - b.width() / 2);
            double dy = Math.max(0, Math.abs(ly) - b.height() / 2);
            if (Math.hypot(dx, dy) <= CLEARANCE) {
                return false;
            }
        }
        return true;
    }

    /** The distance from (x, y) to the segment from (x1, y1) to (x2, y2). */
    private static double segment(double x, double y, double x1, double y1, double x2, double y2) {
        double dx = x2 - x1;
        double dy = y2 - y1;
        double len2 = dx * dx + dy * dy;
        double t = len2 == 0 ? 0 : Math.max(0, Math.min(1, ((x - x1) * dx + (y - y1) * dy) / len2));
        return Math.hypot(x - (x1 + t * dx), y - (y1 + t * dy));
    }
}
