package net.smc.sim.map;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.List;
import java.util.Optional;

/**
 * A* on an {@link OccupancyGrid}, 8-connected without cutting corners. A cell is closed to the
 * robot when an occupied cell lies within {@code clearance} of it (the robot's radius and a little
 * room), or when its centre lies within an avoided zone grown by the margin and by half a cell's
 * diagonal (so no point of an open cell is inside the zone plus margin). Unknown cells are open but
 * cost {@link #UNKNOWN_COST} times a free one, so known routes are preferred. A robot standing in a
 * closed region (beside another robot or a wall, or inside a zone it has just been told to avoid)
 * may cross its closed cells, never an occupied one, until it reaches an open cell; each costs
 * {@link #CLOSED_COST} times a free one, and each step must bring it closer to the nearest open
 * cell ({@link #escapeDepths}), so it leaves by a shortest way out. Without that rule the closed
 * band along a wall was a road through it: a robot standing beside a wall whose cells on the wall
 * line the ring had left free (rays grazing the wall free the cells it straddles) was given paths
 * across the wall, to the open cells on its far side.
 */
public final class PathPlanner {
    /** The cost factor of crossing an unknown cell. */
    public static final double UNKNOWN_COST = 1.5;
    /** The cost factor of crossing a closed cell on the way out of the closed region the robot stands in. */
    public static final double CLOSED_COST = 4;

    private final double clearance;

    /**
     * @param clearance metres to keep between the robot's centre and any occupied cell, not negative
     */
    public PathPlanner(double clearance) {
        if (!(clearance >= 0) || !Double.isFinite(clearance)) {
            throw new IllegalArgumentException("planner clearance " + clearance + " must be a finite number of metres, 0 or more");
        }
        this.clearance = clearance;
    }

    /** Which cells are closed, by {@code col + row * cols}. */
    public boolean[] closedCells(OccupancyGrid grid, List<Zone> avoid, double margin) {
        int cols = grid.cols();
        int rows = grid.rows();
        boolean[] closed = new boolean[cols * rows];
        int reach = (int) Math.ceil(clearance / grid.resolution());
        int side = 2 * reach + 1;
        // the offsets within the clearance, worked out once rather than around every occupied cell
        boolean[] within = new boolean[side * side];
        for (int dr = -reach; dr <= reach; dr++) {
            for (int dc = -reach; dc <= reach; dc++) {
                within[(dc + reach) + (dr + reach) * side] = Math.hypot(dc, dr) * grid.resolution() <= clearance + 1e-9;
            }
        }
        for (int r = 0; r < rows; r++) {
            for (int c = 0; c < cols; c++) {
                if (!grid.isOccupied(c, r)) {
                    continue;
                }
                for (int dr = -reach; dr <= reach; dr++) {
                    for (int dc = -reach; dc <= reach; dc++) {
                        if (within[(dc + reach) + (dr + reach) * side] && grid.inside(c + dc, r + dr)) {
                            closed[(c + dc) + (r + dr) * cols] = true;
                        }
                    }
                }
            }
        }
        double halfDiagonal = grid.resolution() * Math.sqrt(0.5);
        for (Zone zone : avoid) {
            // only the cells round the zone can have their centre in it: a cell more beyond its
            // reach, so that rounding cannot leave one out
            double reachOfZone = zone.radius() + margin + halfDiagonal;
            double res = grid.resolution();
            int fromC = cellIndex(Math.floor((zone.x() - reachOfZone - grid.minX()) / res) - 1, cols);
            int toC = cellIndex(Math.floor((zone.x() + reachOfZone - grid.minX()) / res) + 1, cols);
            int fromR = cellIndex(Math.floor((zone.y() - reachOfZone - grid.minY()) / res) - 1, rows);
            int toR = cellIndex(Math.floor((zone.y() + reachOfZone - grid.minY()) / res) + 1, rows);
            for (int r = fromR; r <= toR; r++) {
                for (int c = fromC; c <= toC; c++) {
                    Point p = grid.centre(c, r);
                    if (zone.contains(p.x(), p.y(), margin + halfDiagonal)) {
                        closed[c + r * cols] = true;
                    }
                }
            }
        }
        return closed;
    }

    /** A column or row index clamped to {@code [0, n)}; worked out in doubles, so an infinite reach cannot overflow. */
    private static int cellIndex(double index, int n) {
        return (int) Math.max(0, Math.min(n - 1, index));
    }

    /**
     * How many steps each cell lies from the nearest open cell, by {@code col + row * cols}: 0 for
     * an open cell, {@link Integer#MAX_VALUE} for an occupied cell or a closed one with no way out.
     * A step goes to any of the 8 neighbours that is not occupied, diagonally only when neither
     * cell beside the diagonal is occupied: the steps by which a robot may leave a closed region.
     *
     * @param closed the closed cells ({@link #closedCells}) of {@code grid}
     * @throws IllegalArgumentException when {@code closed} does not have one entry per cell of {@code grid}
     */
    public static int[] escapeDepths(OccupancyGrid grid, boolean[] closed) {
        int cols = grid.cols();
        if (closed.length != cols * grid.rows()) {
            throw new IllegalArgumentException("closed cells: " + closed.length + " entries for a grid of "
                    + cols * grid.rows() + " cells (" + grid.describe() + "); one entry per cell");
        }
        int[] depth = new int[closed.length];
        int[] queue = new int[closed.length];
        int head = 0;
        int tail = 0;
        for (int i = 0; i < closed.length; i++) {
            if (closed[i]) {
                depth[i] = Integer.MAX_VALUE;
            } else {
                queue[tail++] = i;
            }
        }
        while (head < tail) {
            int cell = queue[head++];
            int c = cell % cols;
            int r = cell / cols;
            for (int dr = -1; dr <= 1; dr++) {
                for (int dc = -1; dc <= 1; dc++) {
                    if ((dc == 0 && dr == 0) || !grid.inside(c + dc, r + dr)) {
                        continue;
                    }
                    int next = (c + dc) + (r + dr) * cols;
                    if (depth[next] != Integer.MAX_VALUE || grid.isOccupied(c + dc, r + dr)
                            || dc != 0 && dr != 0 && (grid.isOccupied(c + dc, r) || grid.isOccupied(c, r + dr))) {
                        continue;
                    }
                    depth[next] = depth[cell] + 1;
                    queue[tail++] = next;
                }
            }
        }
        return depth;
    }

    /**
     * A path from {@code start} to {@code goal}: the waypoints after the start cell, ending at the
     * goal itself; empty when the goal is off the grid, closed, or cannot be reached. The start
     * cell may be closed (the robot may stand close to an obstacle, or in a zone): the path then
     * first crosses the closed region around it, through cells that are not occupied, each nearer
     * an open cell than the one before ({@link #escapeDepths}).
     */
    public Optional<List<Point>> plan(OccupancyGrid grid, Point start, Point goal, List<Zone> avoid, double margin) {
        if (!grid.covers(goal.x(), goal.y())) {
            return Optional.empty();
        }
        for (Zone zone : avoid) {
            if (zone.contains(goal.x(), goal.y(), margin)) {
                return Optional.empty();
            }
        }
        boolean[] closed = closedCells(grid, avoid, margin);
        int cols = grid.cols();
        int startC = Math.max(0, Math.min(cols - 1, grid.col(start.x())));
        int startR = Math.max(0, Math.min(grid.rows() - 1, grid.row(start.y())));
        int goalC = grid.col(goal.x());
        int goalR = grid.row(goal.y());
        int s = startC + startR * cols;
        int g = goalC + goalR * cols;
        if (closed[g] && g != s) {
            return Optional.empty();
        }
        double[] cost = new double[closed.length];
        int[] from = new int[closed.length];
        Arrays.fill(cost, Double.POSITIVE_INFINITY);
        Arrays.fill(from, -1);
        cost[s] = 0;
        OpenCells open = new OpenCells();
        open.add(heuristic(startC, startR, goalC, goalR), s);
        boolean[] done = new boolean[closed.length];
        int[] depth = closed[s] ? escapeDepths(grid, closed) : null;
        while (!open.isEmpty()) {
            int cell = open.poll();
            if (done[cell]) {
                continue;
            }
            done[cell] = true;
            if (cell == g) {
                return Optional.of(waypoints(grid, from, s, g, goal));
            }
            int c = cell % cols;
            int r = cell / cols;
            for (int dr = -1; dr <= 1; dr++) {
                for (int dc = -1; dc <= 1; dc++) {
                    if ((dc == 0 && dr == 0) || !grid.inside(c + dc, r + dr)) {
                        continue;
                    }
                    int next = (c + dc) + (r + dr) * cols;
                    // Closed cells are reached only from the start's closed region: from there, any
                    // cell not occupied and nearer an open cell may be entered, until the path
                    // reaches an open cell.
                    boolean leaving = closed[cell];
                    if (done[next] || closed[next] && (!leaving || grid.isOccupied(c + dc, r + dr) || depth[next] >= depth[cell])) {
                        continue;
                    }
                    if (dc != 0 && dr != 0 && (leaving
                            ? grid.isOccupied(c + dc, r) || grid.isOccupied(c, r + dr)
                            : closed[(c + dc) + r * cols] || closed[c + (r + dr) * cols])) {
                        continue;
                    }
                    double step = (dc != 0 && dr != 0 ? Math.sqrt(2) : 1)
                            * (grid.isKnown(c + dc, r + dr) ? 1 : UNKNOWN_COST) * (closed[next] ? CLOSED_COST : 1);
                    if (cost[cell] + step < cost[next]) {
                        cost[next] = cost[cell] + step;
                        from[next] = cell;
                        open.add(cost[next] + heuristic(c + dc, r + dr, goalC, goalR), next);
                    }
                }
            }
        }
        return Optional.empty();
    }

    /**
     * Whether a path from {@code start} through {@code waypoints} still crosses only open cells
     * (at this planner's clearance, keeping out of the zones plus the margin): each leg is looked
     * at every quarter cell. A robot standing in a closed cell has no open path to keep.
     */
    public boolean isOpen(OccupancyGrid grid, Point start, List<Point> waypoints, List<Zone> avoid, double margin) {
        boolean[] closed = closedCells(grid, avoid, margin);
        Point from = start;
        for (Point to : waypoints) {
            int steps = Math.max(1, (int) Math.ceil(from.distanceTo(to.x(), to.y()) / (grid.resolution() / 4)));
            for (int i = 0; i <= steps; i++) {
                double t = (double) i / steps;
                int c = grid.col(from.x() + (to.x() - from.x()) * t);
                int r = grid.row(from.y() + (to.y() - from.y()) * t);
                if (!grid.inside(c, r) || closed[c + r * grid.cols()]) {
                    return false;
                }
            }
            from = to;
        }
        return true;
    }

    /**
     * The open cells of a search by estimated cost, cheapest first: a binary heap on two arrays
     * (no object per entry). Equal estimates leave in the order {@link java.util.PriorityQueue}
     * would give them (the same sifts, the same comparisons), so a search expands the cells it
     * always did and finds the same path.
     */
    private static final class OpenCells {
        private double[] keys = new double[64];
        private int[] cells = new int[64];
        private int size;

        boolean isEmpty() {
            return size == 0;
        }

        void add(double key, int cell) {
            if (size == keys.length) {
                keys = Arrays.copyOf(keys, size * 2);
                cells = Arrays.copyOf(cells, size * 2);
            }
            int k = size++;
            while (k > 0) {
                int parent = (k - 1) >>> 1;
                if (Double.compare(key, keys[parent]) >= 0) {
                    break;
                }
                keys[k] = keys[parent];
                cells[k] = cells[parent];
                k = parent;
            }
            keys[k] = key;
            cells[k] = cell;
        }

        /** Takes out the cheapest cell. */
        int poll() {
            int first = cells[0];
            int n = --size;
            if (n > 0) {
                double key = keys[n];
                int cell = cells[n];
                int k = 0;
                int half = n >>> 1;
                while (k < half) {
                    int child = 2 * k + 1;
                    int right = child + 1;
                    if (right < n && Double.compare(keys[child], keys[right]) > 0) {
                        child = right;
                    }
                    if (Double.compare(key, keys[child]) <= 0) {
                        break;
                    }
                    keys[k] = keys[child];
                    cells[k] = cells[child];
                    k = child;
                }
                keys[k] = key;
                cells[k] = cell;
            }
            return first;
        }
    }

    private static double heuristic(int c, int r, int goalC, int goalR) {
        return Math.hypot(c - goalC, r - goalR);
    }

    /** The cell centres from start to goal, dropping those in the middle of straight runs. */
    private static List<Point> waypoints(OccupancyGrid grid, int[] from, int s, int g, Point goal) {
        int cols = grid.cols();
        List<Integer> cells = new ArrayList<>();
        for (int cell = g; cell != s; cell = from[cell]) {
            cells.add(cell);
        }
        Collections.reverse(cells);
        List<Point> points = new ArrayList<>();
        int prev = s;
        for (int i = 0; i < cells.size() - 1; i++) {
            int here = cells.get(i);
            int next = cells.get(i + 1);
            int d1 = here - prev;
            int d2 = next - here;
            if (d1 != d2) {
                points.add(grid.centre(here % cols, here / cols));
            }
            prev = here;
        }
        points.add(goal);
        return points;
    }
}
