package net.smc.sim.task;

import java.util.ArrayDeque;
import java.util.Collection;
import java.util.List;
import java.util.Objects;
import java.util.Optional;

import net.smc.core.task.Task;
import net.smc.sim.hardware.Pose;
import net.smc.sim.hardware.RobotHardware;
import net.smc.sim.map.OccupancyGrid;
import net.smc.sim.map.PathPlanner;
import net.smc.sim.map.Point;

/**
 * What a robot does while none of its tasks drives it: it does not stay in a narrow passage. A
 * robot whose role changes to one that drives nothing (a surveyor that takes over as commander)
 * stops where its last driving task left it, and that may be a doorway; standing there it closes
 * the room behind to its teammates (their paths keep clear of it, and a detector sent into the
 * room gives its suspect up at the door). So, once no driving task has run for
 * {@link #IDLE_SECONDS}, a robot that a task has driven before and whose map shows it between two
 * obstacles across a way open on both ends ({@link #inPassage}) drives, on the map it has, to the
 * nearest known free place that is no passage, has room round it and lies at least
 * {@link #MIN_MOVE} from where it stood; then it stops there. A driving task that starts takes the
 * wheels back at once. A robot that no task has driven yet stays where it was placed: the robots
 * parked round an aggregator at the house's entrance made a passage on its map, and moving it
 * changed the mission's course for nothing. Not a catalogue task: no role asks for it, every robot
 * has it.
 *
 * <pre>{@code
 * ClearWay.install(context, tasks.values());   // with the robot's tasks, made from the same context
 * }</pre>
 */
public final class ClearWay {
    /** How long no driving task must have run before the robot looks at where it stands, s. */
    static final double IDLE_SECONDS = 2;
    /** How often an idle robot looks again, s. */
    static final double CHECK_SECONDS = 1;
    /** Obstacles this near on both sides of the robot, across an open way, make a passage, m. */
    static final double PASSAGE_HALF_WIDTH = 0.75;
    /** How far the way must be open on both ends for two obstacles beside the robot to be a passage, m. */
    static final double OPEN_ENDS = 0.5;
    /** The room a place to stand needs: no occupied cell's centre within it, m. */
    static final double ROOM = 0.45;
    /** The least distance between where the robot stood and where it goes, m. */
    static final double MIN_MOVE = 1.0;
    /** The farthest, along the free cells, the robot looks for a place to go, m. */
    static final double SEARCH = 3;
    /** How long a move may take before the robot gives it up and stops, s. */
    static final double MOVE_SECONDS = 20;

    private final RobotHardware hardware;
    private final OccupancyGrid map;
    private final Collection<? extends Task> tasks;
    private final PathPlanner planner;
    private final PathFollower follower;
    /** Since when no driving task ran (NaN: one runs). */
    private double idleSince = Double.NaN;
    /** Whether a driving task has run on this robot (since its first boot: carried over when its cell boots again). */
    private boolean everDriven;
    private double nextCheck = Double.NEGATIVE_INFINITY;
    /** When the current move began (NaN: none). */
    private double movingSince = Double.NaN;

    private ClearWay(RobotHardware hardware, OccupancyGrid map, Collection<? extends Task> tasks) {
        this.hardware = hardware;
        this.map = map;
        this.tasks = tasks;
        this.planner = new PathPlanner(hardware.drive().wheelBase() / 2 + 0.05);
        this.follower = new PathFollower(hardware, map.resolution(), 0.12);
    }

    /**
     * Gives the robot of {@code context} this behaviour, beside {@code tasks} (its tasks, made from
     * {@code context}: while one of them that drives runs, this one does nothing).
     */
    public static ClearWay install(TaskContext context, Collection<? extends Task> tasks) {
        return install(context, tasks, null);
    }

    /**
     * As {@link #install(TaskContext, Collection)} on a robot whose cell booted again, {@code before}
     * its behaviour until then (removed by the caller): whether a task drove the robot carries over.
     */
    public static ClearWay install(TaskContext context, Collection<? extends Task> tasks, ClearWay before) {
        Objects.requireNonNull(context, "context");
        ClearWay way = new ClearWay(context.hardware(), context.map(), Objects.requireNonNull(tasks, "tasks"));
        way.everDriven = before != null && before.everDriven;
        context.hardware().control(way, way::step);
        return way;
    }

    /** Whether the robot is driving away from a passage now. */
    boolean moving() {
        return follower.active();
    }

    private boolean driven() {
        for (Task t : tasks) {
            if (t instanceof RobotTask r && r.drives() && t.isRunning()) {
                return true;
            }
        }
        return false;
    }

    void step(double time, double dt) {
        if (driven()) {
            everDriven = true;
            idleSince = Double.NaN;
            if (follower.active()) {
                follower.clear(); // the task has the wheels now
                movingSince = Double.NaN;
            }
            return;
        }
        if (!everDriven || !hardware.drive().working()) {
            follower.clear();
            return;
        }
        if (Double.isNaN(idleSince)) {
            idleSince = time;
        }
        if (follower.active()) {
            PathFollower.Status s = follower.step();
            if (s != PathFollower.Status.MOVING || time - movingSince > MOVE_SECONDS) {
                stop(time);
            }
            return;
        }
        if (time - idleSince < IDLE_SECONDS || time < nextCheck) {
            return;
        }
        nextCheck = time + CHECK_SECONDS;
        Pose pose = hardware.odometry().pose();
        int c = map.col(pose.x());
        int r = map.row(pose.y());
        if (!map.inside(c, r) || !inPassage(map, c, r)) {
            return;
        }
        Optional<Point> place = placeAway(map, c, r);
        if (place.isEmpty()) {
            return;
        }
        Optional<List<Point>> path = planner.plan(map, new Point(pose.x(), pose.y()), place.get(), List.of(), 0);
        if (path.isPresent() && !path.get().isEmpty()) {
            follower.follow(path.get(), map.resolution() / 2);
            movingSince = time;
        }
    }

    private void stop(double time) {
        follower.clear();
        hardware.drive().stop();
        movingSince = Double.NaN;
        nextCheck = time + CHECK_SECONDS;
    }

    /**
     * Whether the free cell ({@code c}, {@code r}) lies in a passage on {@code grid}: occupied cells
     * within {@link #PASSAGE_HALF_WIDTH} on both sides along one axis (in the robot's row or column
     * or the one beside it on either hand: a thin wall lies on the edge of two rows, and a map wears
     * one of them away), and the way along the other axis free for {@link #OPEN_ENDS} on both ends
     * (so a robot beside one wall, or in a corner, is in none).
     */
    static boolean inPassage(OccupancyGrid grid, int c, int r) {
        int near = (int) Math.floor(PASSAGE_HALF_WIDTH / grid.resolution() + 0.5);
        int open = (int) Math.ceil(OPEN_ENDS / grid.resolution());
        return (blocked(grid, c, r, 1, 0, near) && blocked(grid, c, r, -1, 0, near)
                        && clear(grid, c, r, 0, 1, open) && clear(grid, c, r, 0, -1, open))
                || (blocked(grid, c, r, 0, 1, near) && blocked(grid, c, r, 0, -1, near)
                        && clear(grid, c, r, 1, 0, open) && clear(grid, c, r, -1, 0, open));
    }

    /**
     * Whether an occupied cell lies within {@code cells} of ({@code c}, {@code r}) in direction
     * ({@code dc}, {@code dr}), on that line or on one of the two beside it.
     */
    private static boolean blocked(OccupancyGrid grid, int c, int r, int dc, int dr, int cells) {
        for (int side = -1; side <= 1; side++) {
            int sc = c + side * dr;   // beside the line: across the direction
            int sr = r + side * dc;
            for (int i = 1; i <= cells; i++) {
                if (grid.inside(sc + i * dc, sr + i * dr) && grid.isOccupied(sc + i * dc, sr + i * dr)) {
                    return true;
                }
            }
        }
        return false;
    }

    /** Whether the {@code cells} cells from ({@code c}, {@code r}) in direction ({@code dc}, {@code dr}) are known free. */
    private static boolean clear(OccupancyGrid grid, int c, int r, int dc, int dr, int cells) {
        for (int i = 1; i <= cells; i++) {
            if (!grid.isFree(c + i * dc, r + i * dr)) {
                return false;
            }
        }
        return true;
    }

    /**
     * The centre of the nearest free cell, along free cells (4-connected) from ({@code c}, {@code r}),
     * at least {@link #MIN_MOVE} and at most {@link #SEARCH} away, that is in no passage and has
     * {@link #ROOM} round it; empty when there is none.
     */
    static Optional<Point> placeAway(OccupancyGrid grid, int c, int r) {
        int cols = grid.cols();
        int[] steps = new int[cols * grid.rows()];
        java.util.Arrays.fill(steps, -1);
        ArrayDeque<int[]> queue = new ArrayDeque<>();
        steps[c + r * cols] = 0;
        queue.add(new int[] {c, r});
        int max = (int) Math.floor(SEARCH / grid.resolution());
        // a cell without ROOM round it is one a planner keeping that much clearance closes
        boolean[] cramped = new PathPlanner(ROOM).closedCells(grid, List.of(), 0);
        int[][] around = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
        while (!queue.isEmpty()) {
            int[] at = queue.poll();
            int d = steps[at[0] + at[1] * cols];
            if (Math.hypot(at[0] - c, at[1] - r) * grid.resolution() >= MIN_MOVE && !cramped[at[0] + at[1] * cols]
                    && !inPassage(grid, at[0], at[1])) {
                return Optional.of(grid.centre(at[0], at[1]));
            }
            if (d >= max) {
                continue;
            }
            for (int[] a : around) {
                int nc = at[0] + a[0];
                int nr = at[1] + a[1];
                if (grid.isFree(nc, nr) && steps[nc + nr * cols] < 0) {
                    steps[nc + nr * cols] = d + 1;
                    queue.add(new int[] {nc, nr});
                }
            }
        }
        return Optional.empty();
    }
}
