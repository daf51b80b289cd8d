package net.smc.sim.map;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.List;
import java.util.Optional;
import java.util.PriorityQueue;
import java.util.Random;

import org.junit.jupiter.api.Test;

/**
 * The planner finds, on any grid, the very path of a plain A* (a {@link PriorityQueue} of
 * {@code [estimate, cell]}, the clearance checked by distance around every occupied cell, a robot
 * in a closed region leaving it through cells that are not occupied, each nearer an open cell): its own
 * open list and its clearance offsets worked out once must change how fast it plans, not which
 * path it gives, since robots follow that path and a run's timeline depends on it. A robot beside
 * a wall leaves the wall's closed band on its own side, not across the wall.
 */
class PathPlannerTest {
    private static final double CLEARANCE = 0.36;

    /**
     * A wall two cells thick (columns 7 and 8, as a wall on the line between two columns is
     * mapped) with one row of its cells left free, as rays grazing the wall leave them, and a
     * doorway a metre wide further up; the robot stands in the wall's closed band. Leaving the band
     * through the free cells of the wall line reached the open cells on the far side: the path went
     * through the wall, and a detector drove into it again and again (seed 9 of the reconnaissance).
     */
    @Test
    void aRobotBesideAWallLeavesItsClosedBandOnItsOwnSide_notThroughTheWallLinesFreeCells() {
        OccupancyGrid grid = new OccupancyGrid(0, 0, 4, 5, 0.25);
        for (int r = 0; r < grid.rows(); r++) {
            for (int c = 0; c < grid.cols(); c++) {
                boolean wall = (c == 7 || c == 8) && r != 7 && (r < 14 || r > 17);
                Point p = grid.centre(c, r);
                if (wall) {
                    grid.markOccupied(p.x(), p.y());
                } else {
                    grid.markFree(p.x(), p.y());
                }
            }
        }
        Point start = grid.centre(6, 7);
        Point goal = grid.centre(12, 7);
        PathPlanner planner = new PathPlanner(CLEARANCE);
        boolean[] closed = planner.closedCells(grid, List.of(), 0);
        assertTrue(closed[6 + 7 * grid.cols()] && closed[7 + 7 * grid.cols()] && closed[8 + 7 * grid.cols()],
                "the robot's cell and the wall line's free cells are closed");
        int[] depth = PathPlanner.escapeDepths(grid, closed);
        assertEquals(1, depth[6 + 7 * grid.cols()], "the robot is a step from the open cells on its side");
        assertEquals(2, depth[7 + 7 * grid.cols()], "the wall line's free cells lie deeper in the closed band");
        assertEquals(Integer.MAX_VALUE, depth[7 + 6 * grid.cols()], "an occupied cell has no way out");
        IllegalArgumentException wrongSize = org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class,
                () -> PathPlanner.escapeDepths(grid, new boolean[3]));
        assertTrue(wrongSize.getMessage().contains("3 entries") && wrongSize.getMessage().contains("320 cells"),
                wrongSize.getMessage());

        List<Point> path = planner.plan(grid, start, goal, List.of(), 0).orElseThrow();
        boolean throughTheDoorway = false;
        List<Point> walked = new ArrayList<>(List.of(start));
        walked.addAll(path);
        for (int i = 1; i < walked.size(); i++) {
            Point a = walked.get(i - 1);
            Point b = walked.get(i);
            for (double t = 0; t <= 1; t += 0.01) {
                double x = a.x() + (b.x() - a.x()) * t;
                double y = a.y() + (b.y() - a.y()) * t;
                assertFalse(x > 1.75 && x < 2.25 && y < 3.5, "the path crosses the wall at " + x + "," + y + ": " + path);
                throughTheDoorway |= x > 1.75 && x < 2.25 && y > 3.5 && y < 4.5;
            }
        }
        assertTrue(throughTheDoorway, "the path goes through the doorway (y 3.5 to 4.5): " + path);
    }

    /** A robot beside another robot or a wall still leaves its closed band, by the shortest way. */
    /** A planned path is open until a cell along it is closed (here by an obstacle marked beside it) or a zone covers it. */
    @Test
    void aPlannedPathIsOpen_untilSomethingBesideItClosesACellAlongIt() {
        OccupancyGrid grid = new OccupancyGrid(0, 0, 5, 5, 0.25);
        for (int r = 0; r < grid.rows(); r++) {
            for (int c = 0; c < grid.cols(); c++) {
                grid.markFree(grid.centre(c, r).x(), grid.centre(c, r).y());
            }
        }
        PathPlanner planner = new PathPlanner(CLEARANCE);
        Point start = new Point(0.6, 2.5);
        List<Point> path = planner.plan(grid, start, new Point(4.4, 2.5), List.of(), 0).orElseThrow();
        assertTrue(planner.isOpen(grid, start, path, List.of(), 0));
        assertFalse(planner.isOpen(grid, start, path, List.of(new Zone(2.5, 2.5, 0.3)), 0), "a zone across it closes it");
        grid.markOccupied(2.6, 2.85);   // beside the path, within the clearance of it
        grid.markOccupied(2.6, 2.85);
        assertFalse(planner.isOpen(grid, start, path, List.of(), 0), "an obstacle within the clearance of it closes it");
        assertTrue(planner.isOpen(grid, start, List.of(new Point(0.6, 4.4), new Point(4.4, 4.4)), List.of(), 0),
                "a path the obstacle is not near stays open");
    }

    @Test
    void aRobotInAClosedBandLeavesItByTheShortestWay() {
        OccupancyGrid grid = new OccupancyGrid(0, 0, 4, 4, 0.25);
        for (int r = 0; r < grid.rows(); r++) {
            for (int c = 0; c < grid.cols(); c++) {
                Point p = grid.centre(c, r);
                if (c == 5 && r == 8) {
                    grid.markOccupied(p.x(), p.y());
                } else {
                    grid.markFree(p.x(), p.y());
                }
            }
        }
        Point start = grid.centre(6, 8);   // beside the occupied cell, in its closed ring
        List<Point> path = new PathPlanner(CLEARANCE).plan(grid, start, grid.centre(14, 8), List.of(), 0).orElseThrow();
        assertEquals(grid.centre(14, 8), path.get(path.size() - 1));
        assertEquals(1, path.size(), "straight out and on: " + path);
    }

    @Test
    void findsThePathOfAPlainAStarOnRandomGrids() {
        Random random = new Random(12);
        int paths = 0;
        for (int trial = 0; trial < 300; trial++) {
            double resolution = 0.1 + 0.1 * random.nextInt(3);
            OccupancyGrid grid = new OccupancyGrid(0, 0, 2 + random.nextInt(5), 2 + random.nextInt(5), resolution);
            int occupied = random.nextInt(40);
            for (int i = 0; i < occupied; i++) {
                grid.markOccupied(random.nextDouble() * grid.cols() * resolution, random.nextDouble() * grid.rows() * resolution);
            }
            for (int i = 0; i < 200; i++) {
                double x = random.nextDouble() * grid.cols() * resolution;
                double y = random.nextDouble() * grid.rows() * resolution;
                if (!grid.isOccupied(grid.col(x), grid.row(y))) {
                    grid.markFree(x, y);
                }
            }
            List<Zone> zones = new ArrayList<>();
            for (int i = random.nextInt(3); i > 0; i--) {
                zones.add(new Zone(random.nextDouble() * grid.cols() * resolution, random.nextDouble() * grid.rows() * resolution,
                        0.1 + random.nextDouble() * 0.5));
            }
            double clearance = random.nextDouble() * 0.4;
            double margin = random.nextDouble() * 0.2;
            Point start = new Point(random.nextDouble() * grid.cols() * resolution, random.nextDouble() * grid.rows() * resolution);
            Point goal = new Point(random.nextDouble() * grid.cols() * resolution, random.nextDouble() * grid.rows() * resolution);
            PathPlanner planner = new PathPlanner(clearance);
            String what = "trial " + trial;
            assertArrayEquals(plainClosed(grid, clearance, zones, margin), planner.closedCells(grid, zones, margin), what);
            Optional<List<Point>> path = planner.plan(grid, start, goal, zones, margin);
            assertEquals(plainPlan(grid, clearance, start, goal, zones, margin), path, what);
            paths += path.isPresent() && path.get().size() > 2 ? 1 : 0;
        }
        assertTrue(paths > 50, "enough trials found a path with turns to compare: " + paths);
    }

    private static boolean[] plainClosed(OccupancyGrid grid, double clearance, List<Zone> avoid, double margin) {
        int cols = grid.cols();
        boolean[] closed = new boolean[cols * grid.rows()];
        int reach = (int) Math.ceil(clearance / grid.resolution());
        for (int r = 0; r < grid.rows(); r++) {
            for (int c = 0; c < cols; c++) {
                for (int dr = -reach; dr <= reach && grid.isOccupied(c, r); dr++) {
                    for (int dc = -reach; dc <= reach; dc++) {
                        if (grid.inside(c + dc, r + dr) && Math.hypot(dc, dr) * grid.resolution() <= clearance + 1e-9) {
                            closed[(c + dc) + (r + dr) * cols] = true;
                        }
                    }
                }
                for (Zone zone : avoid) {
                    Point p = grid.centre(c, r);
                    closed[c + r * cols] |= zone.contains(p.x(), p.y(), margin + grid.resolution() * Math.sqrt(0.5));
                }
            }
        }
        return closed;
    }

    private static Optional<List<Point>> plainPlan(OccupancyGrid grid, double clearance, Point start, Point goal,
                                                   List<Zone> avoid, double margin) {
        if (!grid.covers(goal.x(), goal.y()) || avoid.stream().anyMatch(z -> z.contains(goal.x(), goal.y(), margin))) {
            return Optional.empty();
        }
        boolean[] closed = plainClosed(grid, clearance, avoid, margin);
        int cols = grid.cols();
        int s = Math.max(0, Math.min(cols - 1, grid.col(start.x()))) + Math.max(0, Math.min(grid.rows() - 1, grid.row(start.y()))) * cols;
        int gc = grid.col(goal.x());
        int gr = grid.row(goal.y());
        int g = gc + gr * cols;
        if (closed[g] && g != s) {
            return Optional.empty();
        }
        double[] cost = new double[closed.length];
        int[] from = new int[closed.length];
        Arrays.fill(cost, Double.POSITIVE_INFINITY);
        cost[s] = 0;
        PriorityQueue<double[]> open = new PriorityQueue<>((a, b) -> Double.compare(a[0], b[0]));
        open.add(new double[] {Math.hypot(s % cols - gc, s / cols - gr), s});
        boolean[] done = new boolean[closed.length];
        int[] depth = plainDepths(grid, closed);
        while (!open.isEmpty()) {
            int cell = (int) open.poll()[1];
            if (done[cell]) {
                continue;
            }
            done[cell] = true;
            if (cell == g) {
                return Optional.of(corners(grid, from, s, g, goal));
            }
            int c = cell % cols;
            int r = cell / cols;
            for (int dr = -1; dr <= 1; dr++) {
                for (int dc = -1; dc <= 1; dc++) {
                    if ((dc == 0 && dr == 0) || !grid.inside(c + dc, r + dr)) {
                        continue;
                    }
                    int next = (c + dc) + (r + dr) * cols;
                    // From a closed cell (the closed region the robot stands in) any cell not occupied
                    // and nearer an open cell may be entered.
                    boolean leaving = closed[cell];
                    boolean blocked = closed[next] && (!leaving || grid.isOccupied(c + dc, r + dr) || depth[next] >= depth[cell]);
                    boolean cornerCut = dc != 0 && dr != 0 && (leaving
                            ? grid.isOccupied(c + dc, r) || grid.isOccupied(c, r + dr)
                            : closed[(c + dc) + r * cols] || closed[c + (r + dr) * cols]);
                    if (done[next] || blocked || cornerCut) {
                        continue;
                    }
                    double step = (dc != 0 && dr != 0 ? Math.sqrt(2) : 1) * (grid.isKnown(c + dc, r + dr) ? 1 : PathPlanner.UNKNOWN_COST)
                            * (closed[next] ? PathPlanner.CLOSED_COST : 1);
                    if (cost[cell] + step < cost[next]) {
                        cost[next] = cost[cell] + step;
                        from[next] = cell;
                        open.add(new double[] {cost[next] + Math.hypot(c + dc - gc, r + dr - gr), next});
                    }
                }
            }
        }
        return Optional.empty();
    }

    /** Steps from each cell to the nearest open cell, by relaxing every cell until nothing changes. */
    private static int[] plainDepths(OccupancyGrid grid, boolean[] closed) {
        int cols = grid.cols();
        int[] depth = new int[closed.length];
        for (int i = 0; i < closed.length; i++) {
            depth[i] = closed[i] ? Integer.MAX_VALUE : 0;
        }
        for (boolean changed = true; changed; ) {
            changed = false;
            for (int cell = 0; cell < closed.length; cell++) {
                int c = cell % cols;
                int r = cell / cols;
                if (!closed[cell] || grid.isOccupied(c, r)) {
                    continue;
                }
                for (int dr = -1; dr <= 1; dr++) {
                    for (int dc = -1; dc <= 1; dc++) {
                        boolean diagonalPastAnObstacle = dc != 0 && dr != 0 && (grid.isOccupied(c + dc, r) || grid.isOccupied(c, r + dr));
                        if ((dc != 0 || dr != 0) && grid.inside(c + dc, r + dr) && !diagonalPastAnObstacle) {
                            int d = depth[(c + dc) + (r + dr) * cols];
                            if (d != Integer.MAX_VALUE && d + 1 < depth[cell]) {
                                depth[cell] = d + 1;
                                changed = true;
                            }
                        }
                    }
                }
            }
        }
        return depth;
    }

    private static List<Point> corners(OccupancyGrid grid, int[] from, int s, int g, Point goal) {
        List<Integer> cells = new ArrayList<>();
        for (int cell = g; cell != s; cell = from[cell]) {
            cells.add(cell);
        }
        Collections.reverse(cells);
        List<Point> points = new ArrayList<>();
        int prev = s;
        for (int i = 0; i < cells.size() - 1; i++) {
            if (cells.get(i) - prev != cells.get(i + 1) - cells.get(i)) {
                points.add(grid.centre(cells.get(i) % grid.cols(), cells.get(i) / grid.cols()));
            }
            prev = cells.get(i);
        }
        points.add(goal);
        return points;
    }
}
