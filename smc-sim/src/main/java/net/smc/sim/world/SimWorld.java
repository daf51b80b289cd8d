package net.smc.sim.world;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.TreeMap;

import net.smc.core.transport.Cancellable;
import net.smc.core.transport.sim.SimulationScheduler;
import net.smc.sim.arena.Arena;
import net.smc.sim.arena.ArenaReader;
import net.smc.sim.radio.RadioGround;
import net.smc.sim.radio.RadioSettings;
import net.smc.sim.radio.WorldRadio;
import net.smc.sim.hardware.Radio;
import net.smc.sim.robot.KoalaSpec;
import net.smc.sim.robot.RobotGround;
import net.smc.sim.robot.SimRobot;
import org.dyn4j.dynamics.Body;
import org.dyn4j.dynamics.BodyFixture;
import org.dyn4j.dynamics.ContinuousDetectionMode;
import org.dyn4j.geometry.AABB;
import org.dyn4j.geometry.Ray;
import org.dyn4j.geometry.Vector2;
import org.dyn4j.world.DetectFilter;
import org.dyn4j.world.World;
import org.dyn4j.world.result.DetectResult;
import org.dyn4j.world.result.RaycastResult;

/**
 * The simulated 2-D world: an {@link Arena} built as a dyn4j {@link World}, its Koala-like robots,
 * and the radio between them, stepped at a fixed period by the simulation's
 * {@link SimulationScheduler}, the same virtual clock that drives the cells and the in-memory
 * network. One seed replays a whole run, positions included; nothing reads the wall clock.
 *
 * <pre>{@code
 * SimulationScheduler scheduler = new SimulationScheduler();
 * SimWorld world = SimWorld.builder(ArenaReader.read(Path.of("missions/worlds/rescue.xml")), scheduler)
 *         .seed(7).build();
 * SimRobot surveyor = world.addRobot("s1", "s1");               // at the start position "s1"
 * surveyor.control(this, (time, dt) -> surveyor.drive().setWheelSpeeds(0.3, 0.3));
 * world.start();
 * scheduler.runFor(10_000);                                     // ten seconds of mission time
 * }</pre>
 *
 * <p>Each step: every robot's control loops run (robots in the order they were added), the drives
 * turn the wheels' ramped speeds into body velocities, the physics moves every body and resolves
 * collisions, then odometry, batteries and hazards are updated, the radio refreshes its links when
 * due ({@link RadioSettings#refreshMillis()}), and {@link WorldStepListener}s are told.
 * Single-threaded, like the scheduler.
 */
public final class SimWorld {
    private final Arena arena;
    private final SimulationScheduler scheduler;
    private final int stepMillis;
    private final double dt;
    private final Noise noise;
    private final KoalaSpec defaultSpec;
    private final World<Body> physics = new World<>();
    private final Map<String, SimRobot> robots = new TreeMap<>();
    private final List<SimRobot> order = new ArrayList<>();
    private final List<WorldStepListener> listeners = new ArrayList<>();
    private final WorldRadio radio;
    private final StaticShapes shapes;
    private final RobotGround robotGround = new Surroundings();
    private final List<Body> nearBodies = new ArrayList<>();   // scratch of castRays
    private long steps;
    /** Changes whenever a sensor's reading may change: see {@link RobotGround#moment()}. */
    private long moment;
    private Cancellable ticking;

    private SimWorld(Builder b) {
        arena = b.arena;
        scheduler = b.scheduler;
        stepMillis = b.stepMillis;
        dt = stepMillis / 1000.0;
        noise = new Noise(b.seed);
        defaultSpec = b.spec;
        physics.setGravity(0, 0);
        physics.getSettings().setStepFrequency(dt);
        physics.getSettings().setAtRestDetectionEnabled(false);
        // A Koala moves at most 12 mm per 20 ms step, far less than any wall's thickness: no tunnelling
        // to guard against, and continuous detection is most of a crowded step's cost.
        physics.getSettings().setContinuousDetectionMode(ContinuousDetectionMode.NONE);
        ArenaBodies.build(arena, physics);
        shapes = new StaticShapes(arena);
        radio = new WorldRadio(new Ground(), b.radio, b.seed);
    }

    /** A builder for a world of {@code arena} stepped by {@code scheduler}. */
    public static Builder builder(Arena arena, SimulationScheduler scheduler) {
        return new Builder(arena, scheduler);
    }

    /** Puts a robot with the default spec at the arena's start position {@code startId}. */
    public SimRobot addRobot(String id, String startId) {
        Arena.Start start = arena.start(startId).orElseThrow(() -> new IllegalArgumentException(
                "arena '" + arena.name() + "' has no start '" + startId + "'; its starts are "
                        + arena.starts().stream().map(Arena.Start::id).toList()));
        return addRobot(id, start, defaultSpec);
    }

    /** Puts a robot built to {@code spec} at {@code start}. */
    public SimRobot addRobot(String id, Arena.Start start, KoalaSpec spec) {
        Objects.requireNonNull(id, "id");
        if (robots.containsKey(id) || arena.stations().stream().anyMatch(s -> s.id().equals(id))) {
            throw new IllegalArgumentException("a robot or station called '" + id + "' is in the world already; ids must be unique");
        }
        SimRobot robot = new SimRobot(robotGround, id, order.size(), spec, start);
        physics.addBody(robot.body());
        moment++;
        robots.put(id, robot);
        order.add(robot);
        return robot;
    }

    /** Starts stepping every {@link #stepMillis()} on the scheduler. */
    public void start() {
        if (ticking == null) {
            ticking = scheduler.schedule(stepMillis, this::tick);
        }
    }

    /** Stops stepping; {@link #start()} resumes. */
    public void stop() {
        if (ticking != null) {
            ticking.cancel();
            ticking = null;
        }
    }

    private void tick() {
        ticking = scheduler.schedule(stepMillis, this::tick);
        step();
    }

    /** Runs one step now (the scheduler calls this when started; tests may call it directly). */
    public void step() {
        steps++;
        moment++;   // a new step's noise
        double time = time();
        for (SimRobot robot : order) {
            robot.runControl(time, dt);
        }
        for (SimRobot robot : order) {
            robot.applyDrive(dt);
        }
        physics.step(1);
        moment++;   // the bodies moved
        for (SimRobot robot : order) {
            String cause = robot.afterStep(dt);
            if (cause != null) {
                for (WorldStepListener listener : listeners) {
                    listener.disabled(this, robot, cause);
                }
            }
        }
        radio.stepped();
        for (WorldStepListener listener : listeners) {
            listener.stepped(this);
        }
    }

    public void addListener(WorldStepListener listener) {
        listeners.add(Objects.requireNonNull(listener, "listener"));
    }

    public boolean removeListener(WorldStepListener listener) {
        return listeners.remove(listener);
    }

    public Arena arena() {
        return arena;
    }

    /** The mission time, seconds: the scheduler's clock. */
    public double time() {
        return scheduler.nowMillis() / 1000.0;
    }

    /** How many steps ran. */
    public long steps() {
        return steps;
    }

    /** The step period, ms. */
    public int stepMillis() {
        return stepMillis;
    }

    public Noise noise() {
        return noise;
    }

    /** The robots, in the order they were added. */
    public List<SimRobot> robots() {
        return Collections.unmodifiableList(order);
    }

    /** The robot called {@code id}, or {@code null}. */
    public SimRobot robot(String id) {
        return robots.get(id);
    }

    /** The radio between the robots and the arena's stations; a {@code RadioModel} for the network. */
    public WorldRadio radio() {
        return radio;
    }

    /** The physics world, for sensors and renderers; do not step it or add bodies to it. */
    public World<Body> physics() {
        return physics;
    }

    /**
     * The distance along a ray from (x, y) in direction {@code angle} to the first body other than
     * {@code self}, or {@code Double.POSITIVE_INFINITY} when nothing lies within {@code maxLength}.
     */
    public double castRay(double x, double y, double angle, double maxLength, Body self) {
        RaycastResult<Body, BodyFixture> hit = physics.raycastClosest(new Ray(new Vector2(x, y), angle), maxLength,
                new Only(self));
        return hit == null ? Double.POSITIVE_INFINITY : hit.getRaycast().getDistance();
    }

    /**
     * {@link #castRay} for a fan of rays that start near one another (a robot's sensors): ray
     * {@code i} starts at ({@code x[i]}, {@code y[i]}) in direction {@code angle[i]}, and its distance
     * goes to {@code out[i]}. The broad phase is asked once, for the bodies near the fan, instead of
     * once per ray; each ray is then cast against those bodies alone, with the same narrow phase, so
     * the distances are {@link #castRay}'s.
     */
    public void castRays(double[] x, double[] y, double[] angle, double maxLength, Body self, double[] out) {
        double minX = Double.POSITIVE_INFINITY;
        double minY = Double.POSITIVE_INFINITY;
        double maxX = Double.NEGATIVE_INFINITY;
        double maxY = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < out.length; i++) {
            double ex = x[i] + maxLength * Math.cos(angle[i]);
            double ey = y[i] + maxLength * Math.sin(angle[i]);
            minX = Math.min(minX, Math.min(x[i], ex));
            minY = Math.min(minY, Math.min(y[i], ey));
            maxX = Math.max(maxX, Math.max(x[i], ex));
            maxY = Math.max(maxY, Math.max(y[i], ey));
        }
        Only filter = new Only(self);
        List<Body> near = nearBodies;
        near.clear();
        // a hair larger than the fan, so that rounding never leaves out a body a ray touches
        AABB box = new AABB(minX - 1e-6, minY - 1e-6, maxX + 1e-6, maxY + 1e-6);
        for (DetectResult<Body, BodyFixture> found : physics.detect(box, filter)) {
            if (!near.contains(found.getBody())) {
                near.add(found.getBody());
            }
        }
        for (int i = 0; i < out.length; i++) {
            Ray ray = new Ray(new Vector2(x[i], y[i]), angle[i]);
            double nearest = Double.POSITIVE_INFINITY;
            for (int b = 0; b < near.size(); b++) {   // by index: no iterator per ray
                Body body = near.get(b);
                RaycastResult<Body, BodyFixture> hit = physics.raycastClosest(ray, maxLength, body, filter);
                if (hit != null && hit.getRaycast().getDistance() < nearest) {
                    nearest = hit.getRaycast().getDistance();
                }
            }
            out[i] = nearest;
        }
    }

    /** Whether nothing that occludes (walls, closed doors, obstacles) lies between the two points. */
    public boolean clearLine(double ax, double ay, double bx, double by) {
        return shapes.clear(ax, ay, bx, by);
    }

    /** How many walls and closed doors (the fence included) the straight line between the two points crosses. */
    public int wallsBetween(double ax, double ay, double bx, double by) {
        return shapes.wallsCrossed(ax, ay, bx, by, Integer.MAX_VALUE - 1);
    }

    /**
     * {@link #wallsBetween}, but counting no further than {@code limit + 1}: for a caller to whom
     * any number past {@code limit} means the same.
     */
    public int wallsBetween(double ax, double ay, double bx, double by, int limit) {
        return shapes.wallsCrossed(ax, ay, bx, by, limit);
    }

    /** The world as its radio sees it: robots (in the order added) and stations, their positions, the walls. */
    private final class Ground implements RadioGround {
        private final Map<String, Node> stations = new TreeMap<>();

        Ground() {
            for (Arena.Station s : arena.stations()) {
                stations.put(s.id(), new Node() {
                    @Override
                    public double x() {
                        return s.x();
                    }

                    @Override
                    public double y() {
                        return s.y();
                    }

                    @Override
                    public boolean radioOn() {
                        return true;
                    }
                });
            }
        }

        @Override
        public long steps() {
            return steps;
        }

        @Override
        public int stepMillis() {
            return stepMillis;
        }

        @Override
        public int nodeCount() {
            return order.size() + arena.stations().size();
        }

        @Override
        public Iterable<String> nodeIds() {
            List<String> ids = new ArrayList<>(nodeCount());
            order.forEach(r -> ids.add(r.id()));
            arena.stations().forEach(s -> ids.add(s.id()));
            return ids;
        }

        @Override
        public Node node(String id) {
            SimRobot robot = robots.get(id);
            if (robot == null) {
                return stations.get(id);
            }
            return new Node() {
                @Override
                public double x() {
                    return robot.x();
                }

                @Override
                public double y() {
                    return robot.y();
                }

                @Override
                public boolean radioOn() {
                    return robot.radioOn();
                }
            };
        }

        @Override
        public int wallsBetween(double ax, double ay, double bx, double by, int limit) {
            return shapes.wallsCrossed(ax, ay, bx, by, limit);
        }
    }

    /** The world as its robots see it: the arena, the robots, ray casts, lines of sight, this step's noise, the radio. */
    private final class Surroundings implements RobotGround {
        @Override
        public Arena arena() {
            return arena;
        }

        @Override
        public Iterable<SimRobot> robots() {
            return SimWorld.this.robots();
        }

        @Override
        public void castRays(double[] x, double[] y, double[] angle, double maxLength, Body self, double[] out) {
            SimWorld.this.castRays(x, y, angle, maxLength, self, out);
        }

        @Override
        public boolean clearLine(double ax, double ay, double bx, double by) {
            return shapes.clear(ax, ay, bx, by);
        }

        @Override
        public double gaussian(long stream, int channel) {
            return noise.gaussian(stream, steps, channel);
        }

        @Override
        public long moment() {
            return moment;
        }

        @Override
        public Radio radio(String id) {
            return radio.view(id);
        }

        @Override
        public void radioOff(SimRobot robot) {
            radio.switchedOff(robot.id());
        }
    }

    /** Lets a ray hit every enabled, non-sensor body but {@code self}. */
    private static final class Only extends DetectFilter<Body, BodyFixture> {
        private final Body self;

        Only(Body self) {
            super(true, true, null);
            this.self = self;
        }

        @Override
        public boolean isAllowed(Body body, BodyFixture fixture) {
            return body != self && super.isAllowed(body, fixture);
        }
    }

    /** Builds a {@link SimWorld}. */
    public static final class Builder {
        private final Arena arena;
        private final SimulationScheduler scheduler;
        private long seed = 1;
        private int stepMillis = 20;
        private KoalaSpec spec = KoalaSpec.koala();
        private RadioSettings radio = RadioSettings.defaults();

        private Builder(Arena arena, SimulationScheduler scheduler) {
            this.arena = Objects.requireNonNull(arena, "arena");
            this.scheduler = Objects.requireNonNull(scheduler, "scheduler");
        }

        /** The seed of every random draw in the world (sensor noise, radio loss). Default 1. */
        public Builder seed(long seed) {
            this.seed = seed;
            return this;
        }

        /** The step period, 1 to 1,000 ms. Default 20 ms. */
        public Builder stepMillis(int stepMillis) {
            if (stepMillis < 1 || stepMillis > 1_000) {
                throw new IllegalArgumentException("step of " + stepMillis + " ms is out of range; it must be 1 to 1000 ms");
            }
            this.stepMillis = stepMillis;
            return this;
        }

        /** The spec of robots added by start id alone. Default {@link KoalaSpec#koala()}. */
        public Builder robotSpec(KoalaSpec spec) {
            this.spec = Objects.requireNonNull(spec, "spec");
            return this;
        }

        public Builder radio(RadioSettings radio) {
            this.radio = Objects.requireNonNull(radio, "radio");
            return this;
        }

        public SimWorld build() {
            return new SimWorld(this);
        }
    }
}
