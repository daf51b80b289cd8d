package net.smc.sim.task;

import java.util.ArrayDeque;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import net.smc.policy.api.ArrayValue;
import net.smc.sim.hardware.Pose;
import net.smc.sim.hardware.RobotHardware;
import net.smc.sim.hardware.Sighting;
import net.smc.sim.map.OccupancyGrid;
import net.smc.sim.map.PathPlanner;
import net.smc.sim.map.Point;
import net.smc.sim.map.Zone;

/**
 * Frontier exploration: while it runs it fills the robot's occupancy grid from the infrared ring
 * and the odometry, reports new obstacles and camera sightings, and, once told to
 * {@link #explore()}, drives to the nearest reachable frontier (a free cell next to an unknown one,
 * found by breadth-first search over open cells), then the next, until none is left. Paths keep
 * {@link #CLEARANCE} from occupied cells: on the 0.25 m grid that closes the ring of cells around
 * each one, which leaves the middle two cells of a 1 m doorway open and keeps the 0.32 m body off
 * the jambs; when no frontier is open with that clearance it plans with less: the body's
 * half-width and 5 cm. Something in the way makes it back off and plan again to the same frontier, up to
 * {@link #OBSTRUCTIONS} times. A frontier it gave up on (no way there, stalled, obstructed) is set
 * aside with the frontier cells within {@link SetAsideFrontiers#RADIUS} of it, for
 * {@link #SET_ASIDE_SECONDS} the first time and twice as long at each further failure there, up to
 * {@link SetAsideFrontiers#MAX_SECONDS}: the rest of the house is explored first, and the way there may be
 * open by then (a robot stood in a doorway, say). A frontier whose unknown side stays unknown while
 * the robot stands within {@link #LOOKED_FROM} of it for {@link #LOOK_SECONDS} (or on it) lies
 * behind something the ring cannot see past: a cell straddling a wall, whose unknown neighbour is
 * the far side of the wall, is the common case. Those unknown cells are taken to be hidden and make
 * no frontier for this robot again; without that, such cells along every wall drew the robot back
 * again and again. For the same reason a cell the ring has struck is no frontier even when rays
 * passing beside it have freed it since. Told where a failed teammate's body lies
 * ({@link #pushAside}), it plans with that body's cells taken for free and pushes the body aside
 * when it is in the way (the path follower drives on slowly into it): a robot that died in a
 * doorway would otherwise seal the rooms behind it. A body that gives way is known from then on where
 * it was pushed to ({@link PathFollower#takePush}), so that a body pushed into a doorway is pushed on,
 * not taken for a wall. A target is given up when the robot, driving,
 * stays within 5 cm for {@link #STALL_SECONDS} or within {@link #CREEP_MOVED} for
 * {@link #CREEP_SECONDS}: the second tells a robot pushing into a body that does not give, whose
 * position jitters by a few centimetres.
 */
public final class Explorer extends RobotTask implements ExplorerI, Handover {
    private static final double REPORT_STEP = 0.1;
    /** The steps to a cell's 4-connected neighbours. */
    private static final int[][] FOUR_NEIGHBOURS = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    /** Seconds of driving without moving 5 cm after which the target is given up. */
    private static final double STALL_SECONDS = 4;
    /**
     * Seconds of driving without getting {@link #CREEP_MOVED} from where it was after which the
     * target is given up: a robot pushing into something that does not give (a body against a jamb,
     * say) creeps by a few centimetres at a time, which the {@link #STALL_SECONDS} watch takes for moves.
     */
    static final double CREEP_SECONDS = 15;
    /** Less than this, in metres, is no progress for the {@link #CREEP_SECONDS} watch. */
    static final double CREEP_MOVED = 0.3;
    /** Metres kept between the robot's centre and an occupied cell's centre when planning. */
    static final double CLEARANCE = 0.36;
    /** How often something in the way may stop the robot on its way to one frontier before it gives that frontier up. */
    static final int OBSTRUCTIONS = 3;
    /** How long a frontier given up on is set aside the first time, s. */
    static final double SET_ASIDE_SECONDS = SetAsideFrontiers.FIRST_SECONDS;
    /**
     * How close to a frontier cell the robot must come for its ring (2 m in the house) to have seen
     * past it, m: an unknown cell beside it that is still unknown then lies behind something (the
     * far side of a wall the cell straddles, say) and is taken to be hidden from this robot.
     */
    static final double LOOKED_FROM = 0.6;
    /** How long the robot must stay within {@link #LOOKED_FROM} of its frontier before its unknown side is taken to be hidden, s. */
    static final double LOOK_SECONDS = 1.5;
    /** A frontier given up on (obstructed, stalled) this close has its unknown side taken to be hidden, m. */
    static final double GAVE_UP_NEAR = 1.0;

    private final OccupancyGrid map;
    private final PathPlanner planner;
    private final PathPlanner narrow;
    private PathPlanner current;
    private final PathFollower follower;
    private final Set<Integer> reportedObstacles = new HashSet<>();
    private final SetAsideFrontiers setAside;
    private final Set<Integer> hidden = new HashSet<>();
    private final boolean[] struck;
    private final Set<String> sighted = new HashSet<>();
    private final List<Zone> zones = new java.util.ArrayList<>();
    private final FailedBodies bodies = new FailedBodies();
    private boolean pushing;
    private boolean exploring;
    private int target = -1;
    private double reported;
    private double backOffUntil = -1;
    private int sharedKnown = -1;
    private final StallWatch stall = new StallWatch(STALL_SECONDS);
    private final StallWatch creep = new StallWatch(CREEP_SECONDS, CREEP_MOVED);
    private int obstructed;
    private double now;
    private double nearSince = Double.NaN;

    public Explorer(TaskContext context) {
        this(context.hardware(), context.map());
    }

    public Explorer(RobotHardware hardware, OccupancyGrid map) {
        super(hardware);
        this.map = java.util.Objects.requireNonNull(map, "map");
        this.struck = new boolean[map.cols() * map.rows()];
        this.setAside = new SetAsideFrontiers(map);
        this.planner = new PathPlanner(CLEARANCE);
        this.narrow = new PathPlanner(narrowClearance());
        this.current = planner;
        this.follower = new PathFollower(hardware, map.resolution(), 0.12);
    }

    public OccupancyGrid map() {
        return map;
    }

    @Override
    public void explore() {
        exploring = true;
        target = -1;
        creep.reset();   // the time it stood halted is no time spent getting nowhere
    }

    @Override
    public void halt() {
        exploring = false;
        target = -1;
        follower.clear();
        hardware.drive().stop();
    }

    @Override
    public void avoid(double x, double y, double radius) {
        StateValues.finite("Explorer avoid x", x);
        StateValues.finite("Explorer avoid y", y);
        if (!(radius > 0) || !Double.isFinite(radius)) {
            throw new IllegalArgumentException("Explorer avoid: radius " + radius + " must be a positive number of metres");
        }
        zones.add(new Zone(x, y, radius));
        follower.clear();
        target = -1;
    }

    @Override
    public void pushAside(double x, double y) {
        StateValues.finite("Explorer pushAside x", x);
        StateValues.finite("Explorer pushAside y", y);
        if (!bodies.add(new Point(x, y))) {
            return;   // told again (a surveyor announces the bodies it knows of every few seconds)
        }
        // what the body hid from the ring is not hidden for good: it may be pushed away
        hidden.removeIf(cell -> bodies.behind(map, cell % map.cols(), cell / map.cols()));
    }

    /** The failed teammates' bodies it was told of ({@link #pushAside}). */
    List<Point> bodies() {
        return bodies.points();
    }

    /** The zones it keeps out of. */
    public List<Zone> zones() {
        return List.copyOf(zones);
    }

    @Override
    public void shareMap() {
        if (map.knownCells() == sharedKnown) {
            return;
        }
        sharedKnown = map.knownCells();
        @SuppressWarnings("unchecked")
        List<String> rows = (List<String>) map.toState().get("cells");
        mapUpdate("mapUpdate", hardware.id(), rows);
    }

    @Override
    public void merge(ArrayValue cells) {
        java.util.Objects.requireNonNull(cells, "cells");
        Map<String, Object> state = map.toState();
        state.put("cells", cells.items());
        map.fillUnknown(OccupancyGrid.fromState(state));
    }

    @Override
    public void mapUpdate(String name, String uav, List<String> cells) {
        raise("mapUpdate", name, uav, cells);
    }

    @Override
    public double exploredFraction() {
        return map.exploredFraction();
    }

    @Override
    public boolean isExploring() {
        return exploring;
    }

    @Override
    public void obstacle(double x, double y) {
        raise("obstacle", x, y);
    }

    @Override
    public void areaExplored(double fraction, boolean done) {
        raise("areaExplored", fraction, done);
    }

    @Override
    public void targetSighted(String tag, String kind, double x, double y) {
        raise("targetSighted", tag, kind, x, y);
    }

    @Override
    protected boolean drives() {
        return true;
    }

    @Override
    protected void step(double time, double dt) {
        now = time;
        for (Point hit : RangeMapper.observe(hardware, map)) {
            int cell = map.col(hit.x()) + map.row(hit.y()) * map.cols();
            if (map.covers(hit.x(), hit.y())) {
                struck[cell] = true;
                if (reportedObstacles.add(cell)) {
                    obstacle(hit.x(), hit.y());
                }
            }
        }
        look();
        double fraction = map.exploredFraction();
        if (fraction >= reported + REPORT_STEP) {
            reported = Math.floor(fraction / REPORT_STEP) * REPORT_STEP;
            areaExplored(fraction, false);
        }
        if (exploring) {
            drive(time);
        }
    }

    private void look() {
        if (!hardware.has(RobotHardware.Device.CAMERA)) {
            return;
        }
        Pose pose = hardware.odometry().pose();
        for (Sighting s : hardware.camera().look()) {
            if (sighted.add(s.tag())) {
                double a = pose.heading() + s.bearing();
                targetSighted(s.tag(), s.kind(), pose.x() + Math.cos(a) * s.distance(), pose.y() + Math.sin(a) * s.distance());
            }
        }
    }

    private void drive(double time) {
        if (time < backOffUntil) {
            double back = -0.3 * hardware.drive().maxSpeed();
            hardware.drive().setWheelSpeeds(back, back);
            return;
        }
        if (target >= 0 && !frontier(pushing ? bodies.without(map) : map, target % map.cols(), target / map.cols())) {
            target = -1;
        }
        Pose pose = hardware.odometry().pose();
        if (target >= 0 && near(pose, target, LOOKED_FROM)) {
            if (Double.isNaN(nearSince)) {
                nearSince = time;
            } else if (time - nearSince >= LOOK_SECONDS) {
                // Close for long enough for the ring to have seen past it: what is still unknown there is hidden.
                hide(target);
                follower.clear();
                target = -1;
            }
        }
        if (target < 0 && !chooseTarget(pose)) {
            exploring = false;
            follower.clear();
            hardware.drive().stop();
            areaExplored(map.exploredFraction(), true);
            return;
        }
        PathFollower.Status st = follower.step();
        follower.takePush().ifPresent(p -> bodies.moved(p.body(), p.now()));
        switch (st) {
            case ARRIVED, IDLE -> {
                // Standing on it, the robot saw what it could: what is still unknown there is hidden.
                hide(target);
                target = -1;
            }
            case OBSTRUCTED -> {
                if (++obstructed >= OBSTRUCTIONS || !replan(pose)) {
                    giveUpTarget(time);
                } else {
                    backOffUntil = time + 0.5;
                }
            }
            default -> {
                if (stall.stalled(time, pose) | creep.stalled(time, pose)) {
                    giveUpTarget(time);
                }
            }
        }
    }

    /**
     * Picks the nearest frontier open to the robot with the full {@link #CLEARANCE} and, when none
     * is, with only the body's half-width and 5 cm (a doorway narrowed on the map by a robot
     * standing in it, say, or by a stray reading); whether one was found.
     * Once told of failed teammates' bodies ({@link #pushAside}) it plans on the map with their
     * cells taken for free ({@link FailedBodies#without}), and the path follower may push them.
     */
    private boolean chooseTarget(Pose pose) {
        // Around the bodies first; through them, pushing, only when that leaves no frontier open.
        if (chooseTarget(pose, false)) {
            return true;
        }
        return !bodies.isEmpty() && chooseTarget(pose, true);
    }

    private boolean chooseTarget(Pose pose, boolean push) {
        OccupancyGrid grid = push ? bodies.without(map) : map;
        for (PathPlanner p : List.of(planner, narrow)) {
            Set<Integer> failed = new HashSet<>();
            while (true) {
                Optional<Integer> next = nearestFrontier(pose, p, grid, failed);
                if (next.isEmpty()) {
                    break;
                }
                Point goal = map.centre(next.get() % map.cols(), next.get() / map.cols());
                Optional<List<Point>> path = p.plan(grid, new Point(pose.x(), pose.y()), goal, zones, 0);
                if (path.isPresent()) {
                    target = next.get();
                    nearSince = Double.NaN;
                    current = p;
                    pushing = push;
                    follower.pushable(pushing ? bodies.points() : List.of());
                    obstructed = 0;
                    follower.follow(path.get(), map.resolution());
                    return true;
                }
                failed.add(next.get());
                if (p == narrow && (push || bodies.isEmpty())) {
                    setAside.add(next.get(), now);
                }
            }
        }
        return false;
    }

    /** Plans again to the current target on the map as it is now; whether a way is left. */
    private boolean replan(Pose pose) {
        Point p = map.centre(target % map.cols(), target / map.cols());
        Optional<List<Point>> path = current.plan(pushing ? bodies.without(map) : map, new Point(pose.x(), pose.y()), p, zones, 0);
        path.ifPresent(w -> follower.follow(w, map.resolution()));
        return path.isPresent();
    }

    private void giveUpTarget(double time) {
        if (near(hardware.odometry().pose(), target, GAVE_UP_NEAR)) {
            hide(target);
        }
        setAside.add(target, time);
        target = -1;
        follower.clear();
        backOffUntil = time + 0.5;
        stall.reset();
        creep.reset();
    }

    /**
     * A free cell with an unknown neighbour (4-connected) that is not hidden, and that the ring has
     * never struck: one the robot may still learn something from. A struck cell free now holds an
     * edge of something (the cell straddles a wall or a table's side, and rays passing beside the
     * edge freed it): its unknown side is the inside of that thing.
     */
    boolean frontier(int c, int r) {
        return frontier(map, c, r);
    }

    /**
     * The same on {@code grid}: the map, or the map without the failed teammates' bodies
     * ({@link FailedBodies#without}), on which the cells of a body the ring struck may be frontiers.
     */
    private boolean frontier(OccupancyGrid grid, int c, int r) {
        if (!grid.isFree(c, r) || struck[c + r * map.cols()] && (grid == map || !bodies.on(map, c, r))) {
            return false;
        }
        for (int[] s : FOUR_NEIGHBOURS) {
            int nc = c + s[0];
            int nr = r + s[1];
            if (map.inside(nc, nr) && !grid.isKnown(nc, nr) && !hidden.contains(nc + nr * map.cols())) {
                return true;
            }
        }
        return false;
    }

    /** The unknown neighbours of a frontier cell the robot came close to, and still unknown: hidden from its sensors. */
    private void hide(int cell) {
        int c = cell % map.cols();
        int r = cell / map.cols();
        for (int[] s : FOUR_NEIGHBOURS) {
            if (map.inside(c + s[0], r + s[1]) && !map.isKnown(c + s[0], r + s[1]) && !bodies.behind(map, c + s[0], r + s[1])) {
                hidden.add(c + s[0] + (r + s[1]) * map.cols());
            }
        }
    }

    private boolean near(Pose pose, int cell, double metres) {
        Point p = map.centre(cell % map.cols(), cell / map.cols());
        return Math.hypot(p.x() - pose.x(), p.y() - pose.y()) <= metres;
    }

    /**
     * Breadth-first search over cells open to the robot, from its own cell. From a closed cell (the
     * robot stands close to something) any cell not occupied may be entered, so that it can leave.
     */
    private Optional<Integer> nearestFrontier(Pose pose, PathPlanner planner, OccupancyGrid grid, Set<Integer> failed) {
        int cols = map.cols();
        boolean[] closed = planner.closedCells(grid, zones, 0);
        int startC = Math.max(0, Math.min(cols - 1, map.col(pose.x())));
        int startR = Math.max(0, Math.min(map.rows() - 1, map.row(pose.y())));
        int start = startC + startR * cols;
        boolean[] seen = new boolean[closed.length];
        ArrayDeque<Integer> queue = new ArrayDeque<>();
        queue.add(start);
        seen[start] = true;
        while (!queue.isEmpty()) {
            int cell = queue.poll();
            int c = cell % cols;
            int r = cell / cols;
            if (cell != start && frontier(grid, c, r) && !setAside.holds(c, r, now) && !failed.contains(cell)
                    && !grid.besideOccupied(c, r)) {
                return Optional.of(cell);
            }
            for (int[] s : FOUR_NEIGHBOURS) {
                int nc = c + s[0];
                int nr = r + s[1];
                if (!map.inside(nc, nr)) {
                    continue;
                }
                int next = nc + nr * cols;
                if (!seen[next] && (!closed[next] || closed[cell]) && !grid.isOccupied(nc, nr)) {
                    seen[next] = true;
                    if (grid.isKnown(nc, nr)) {
                        queue.add(next);
                    }
                }
            }
        }
        return Optional.empty();
    }

    /**
     * {@code x}, {@code y}, {@code heading}: the robot's last pose by its odometry; {@code map}: the
     * grid ({@link OccupancyGrid#toState()}); {@code exploring}.
     */
    @Override
    public Map<String, Object> exportState() {
        Pose pose = hardware.odometry().pose();
        Map<String, Object> state = new LinkedHashMap<>();
        state.put("x", pose.x());
        state.put("y", pose.y());
        state.put("heading", pose.heading());
        state.put("exploring", exploring);
        state.put("map", map.toState());
        return state;
    }

    /** Merges the handed-over map into this robot's (the position is for policies to act on). */
    @Override
    public void importState(Map<String, ?> state) {
        if (StateValues.has(state, "map")) {
            map.merge(OccupancyGrid.fromState(StateValues.map("Explorer", state, "map")));
        }
        if (state.get("exploring") instanceof Boolean b && b) {
            explore();
        }
    }

    /** Whether the frontier cell is set aside now (for tests). */
    boolean isSetAside(int col, int row) {
        return setAside.holds(col, row, now);
    }
}
