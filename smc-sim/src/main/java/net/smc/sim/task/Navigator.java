package net.smc.sim.task;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import net.smc.sim.hardware.Pose;
import net.smc.sim.hardware.RobotHardware;
import net.smc.sim.map.OccupancyGrid;
import net.smc.sim.map.PathPlanner;
import net.smc.sim.map.Point;
import net.smc.sim.map.Zone;

/**
 * Goes to a point: plans with A* on the robot's map ({@link PathPlanner}), keeping out of avoided
 * zones plus the margin, and follows the path. When no path keeps its clearance it takes one that
 * keeps only the body's half-width and 5 cm (as the {@link Explorer} does): a doorway whose jamb
 * cells the ring has struck leaves too little room at the full clearance. While it drives it keeps
 * mapping from the infrared ring ({@link RangeMapper#observeKeepingWalls}: no ray frees a cell
 * near a point the ring hits, so a wall on a grid line is not worn into gaps the planner takes for
 * ways through it) and looks at its path every second: it keeps a path planned at the
 * full clearance while every cell along it is still open, and plans again when one is closed, when
 * something is in the way (after backing off a little), or when it follows a narrow path (a path
 * at the full clearance may have opened since). Re-planning every second whatever the path, it
 * turned back and forth between two ways of about the same cost as the map changed under it: a
 * wall on the line between two grid columns, whose cells the ring marks occupied near it and
 * rays ending short of it free again from farther off, looked open every other second, and a
 * detector drove to and fro between a doorway and that wall for minutes. It gives up with
 * {@code blocked} when no path is left or it has made no progress for {@link #PATIENCE} seconds.
 * Told where a failed teammate's body lies ({@link #pushAside}), it goes around the body when
 * there is room and otherwise plans through the body's cells ({@link FailedBodies#without}) and
 * pushes it aside: its path follower drives on slowly into what is in front of it near the body
 * instead of stopping. A path through a body counts as narrow, so it is planned again every second.
 */
public final class Navigator extends RobotTask implements NavigatorI, Handover {
    /** Seconds without getting 0.1 m closer before giving up. */
    public static final double PATIENCE = 30;
    private static final double REPLAN_PERIOD = 1.0;
    private static final double BACK_OFF = 0.6;

    private final OccupancyGrid map;
    private final PathPlanner planner;
    private final PathPlanner narrow;
    private final PathFollower follower;
    private final List<Zone> zones = new ArrayList<>();
    private final FailedBodies bodies = new FailedBodies();
    private double margin = 0.5;
    private Point goal;
    private boolean replan;
    private double nextReplan;
    private double backOffUntil = -1;
    private double best;
    private double bestAt;
    /** Whether the path followed was planned at the narrow clearance (none kept the full one). */
    private boolean narrowPath;

    public Navigator(TaskContext context) {
        this(context.hardware(), context.map());
    }

    public Navigator(RobotHardware hardware, OccupancyGrid map) {
        this(hardware, map, hardware.drive().wheelBase() / 2 + 0.1);
    }

    /** A navigator whose paths keep {@code clearance} metres between the robot's centre and occupied cells. */
    Navigator(RobotHardware hardware, OccupancyGrid map, double clearance) {
        super(hardware);
        this.map = java.util.Objects.requireNonNull(map, "map");
        this.planner = new PathPlanner(clearance);
        this.narrow = new PathPlanner(Math.min(clearance, narrowClearance()));
        this.follower = new PathFollower(hardware, map.resolution(), 0.12);
    }

    @Override
    public void goTo(double x, double y) {
        StateValues.finite("goal x", x);
        StateValues.finite("goal y", y);
        if (!map.covers(x, y)) {
            throw new IllegalArgumentException("goal (" + x + ", " + y + ") is off the map (" + map.describe()
                    + "); a goal must lie on the map");
        }
        goal = new Point(x, y);
        replan = true;
        best = Double.POSITIVE_INFINITY;
        bestAt = Double.NaN;
        follower.clear();
    }

    @Override
    public void avoid(double x, double y, double radius) {
        zones.add(new Zone(x, y, radius));
        replan = true;
    }

    @Override
    public void pushAside(double x, double y) {
        StateValues.finite("Navigator pushAside x", x);
        StateValues.finite("Navigator pushAside y", y);
        if (bodies.add(new Point(x, y))) {
            follower.pushable(bodies.points());
            replan = true;
        }
    }

    /** The failed teammates' bodies it was told of ({@link #pushAside}). */
    List<Point> bodies() {
        return bodies.points();
    }

    @Override
    public void clearZones() {
        zones.clear();
        replan = true;
    }

    @Override
    public void margin(double metres) {
        if (!(metres >= 0) || !Double.isFinite(metres)) {
            throw new IllegalArgumentException("Navigator margin " + metres + " must be a finite number of metres, 0 or more");
        }
        margin = metres;
        replan = true;
    }

    @Override
    public void halt() {
        goal = null;
        follower.clear();
        hardware.drive().stop();
    }

    @Override
    public boolean isMoving() {
        return goal != null;
    }

    public List<Zone> zones() {
        return List.copyOf(zones);
    }

    public double margin() {
        return margin;
    }

    public Optional<Point> goal() {
        return Optional.ofNullable(goal);
    }

    @Override
    public void arrived(double x, double y) {
        raise("arrived", x, y);
    }

    @Override
    public void blocked(double x, double y) {
        raise("blocked", x, y);
    }

    @Override
    protected boolean drives() {
        return true;
    }

    @Override
    protected void step(double time, double dt) {
        RangeMapper.observeKeepingWalls(hardware, map);
        if (goal == null) {
            return;
        }
        Pose pose = hardware.odometry().pose();
        double distance = goal.distanceTo(pose.x(), pose.y());
        if (Double.isNaN(bestAt) || distance < best - 0.1) {
            best = distance;
            bestAt = time;
        } else if (time - bestAt > PATIENCE) {
            giveUp();
            return;
        }
        if (time < backOffUntil) {
            double back = -0.3 * hardware.drive().maxSpeed();
            hardware.drive().setWheelSpeeds(back, back);
            return;
        }
        if (replan || time >= nextReplan || !follower.active()) {
            boolean keep = !replan && follower.active() && !narrowPath
                    && planner.isOpen(map, new Point(pose.x(), pose.y()), follower.remaining(), zones, margin);
            replan = false;
            nextReplan = time + REPLAN_PERIOD;
            if (!keep) {
                Point from = new Point(pose.x(), pose.y());
                Optional<List<Point>> path = planner.plan(map, from, goal, zones, margin);
                narrowPath = path.isEmpty();
                if (path.isEmpty()) {
                    path = narrow.plan(map, from, goal, zones, margin);
                }
                if (path.isEmpty() && !bodies.isEmpty()) {
                    path = plan(bodies.without(map), from);
                }
                if (path.isEmpty()) {
                    giveUp();
                    return;
                }
                follower.follow(path.get(), map.resolution() / 2);
            }
        }
        PathFollower.Status status = follower.step();
        follower.takePush().ifPresent(p -> bodies.moved(p.body(), p.now()));
        switch (status) {
            case ARRIVED -> {
                Point reached = goal;
                goal = null;
                arrived(reached.x(), reached.y());
            }
            case OBSTRUCTED -> {
                backOffUntil = time + BACK_OFF;
                replan = true;
            }
            default -> { }
        }
    }

    /** A path to the goal on {@code grid} at the full clearance, else at the narrow one. */
    private Optional<List<Point>> plan(OccupancyGrid grid, Point from) {
        Optional<List<Point>> path = planner.plan(grid, from, goal, zones, margin);
        return path.isPresent() ? path : narrow.plan(grid, from, goal, zones, margin);
    }

    private void giveUp() {
        Point lost = goal;
        goal = null;
        follower.clear();
        hardware.drive().stop();
        blocked(lost.x(), lost.y());
    }

    /** {@code goal} ([x, y], absent when idle), {@code margin}, {@code zones} ([[x, y, radius] ...]). */
    @Override
    public Map<String, Object> exportState() {
        Map<String, Object> state = new LinkedHashMap<>();
        if (goal != null) {
            state.put("goal", List.of(goal.x(), goal.y()));
        }
        state.put("margin", margin);
        List<Object> list = new ArrayList<>();
        for (Zone z : zones) {
            list.add(List.of(z.x(), z.y(), z.radius()));
        }
        state.put("zones", list);
        return state;
    }

    @Override
    public void importState(Map<String, ?> state) {
        List<Zone> imported = new ArrayList<>();
        if (StateValues.has(state, "zones")) {
            for (Object o : StateValues.list("Navigator", state, "zones")) {
                imported.add(zoneOf(o));
            }
        }
        if (StateValues.has(state, "margin")) {
            margin(StateValues.number("Navigator", state, "margin"));
        }
        zones.addAll(imported);
        if (StateValues.has(state, "goal")) {
            List<?> g = StateValues.list("Navigator", state, "goal");
            if (g.size() != 2 || !(g.get(0) instanceof Number x) || !(g.get(1) instanceof Number y)) {
                throw new IllegalArgumentException("Navigator state: 'goal' must be [x, y], got " + g);
            }
            goTo(x.doubleValue(), y.doubleValue());
        }
    }

    private static Zone zoneOf(Object o) {
        if (o instanceof List<?> l && l.size() == 3 && l.get(0) instanceof Number x && l.get(1) instanceof Number y
                && l.get(2) instanceof Number r) {
            return new Zone(x.doubleValue(), y.doubleValue(), r.doubleValue());
        }
        throw new IllegalArgumentException("Navigator state: each of 'zones' must be [x, y, radius], got " + o);
    }
}
