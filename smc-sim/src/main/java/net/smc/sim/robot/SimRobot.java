package net.smc.sim.robot;

import java.util.EnumSet;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Objects;
import java.util.Set;

import net.smc.sim.hardware.Battery;
import net.smc.sim.hardware.Camera;
import net.smc.sim.hardware.ChemicalSensor;
import net.smc.sim.hardware.ControlLoop;
import net.smc.sim.hardware.Drive;
import net.smc.sim.hardware.Odometry;
import net.smc.sim.hardware.Pose;
import net.smc.sim.hardware.ProximitySensors;
import net.smc.sim.hardware.Radio;
import net.smc.sim.hardware.RobotHardware;
import net.smc.sim.arena.Arena;
import net.smc.sim.arena.Arena.Hazard;
import net.smc.sim.arena.Thing;
import org.dyn4j.dynamics.Body;
import org.dyn4j.dynamics.BodyFixture;
import org.dyn4j.geometry.Geometry;
import org.dyn4j.geometry.MassType;

/**
 * A simulated Koala-like robot in a world it sees through a {@link RobotGround}: a rectangular dyn4j body moved by a
 * differential drive (wheel speeds ramped within the acceleration limit, turned into body
 * velocities each step, so collisions with walls and robots are the physics engine's), with
 * noisy wheel odometry, 16 infrared ray-cast sensors, a forward camera, a chemical sensor, a
 * battery that drains with motion, and a radio. Made by {@link net.smc.sim.world.SimWorld#addRobot}; the world calls
 * {@link #runControl}, {@link #applyDrive} and {@link #afterStep} each step.
 */
public final class SimRobot implements RobotHardware {
    private final RobotGround ground;
    private final String id;
    private final int index;
    private final KoalaSpec spec;
    private final Body body;
    private final Motors motors;
    private final WheelOdometry odometry;
    private final PowerCell battery;
    private final InfraredRing proximity;
    private final ForwardCamera camera;
    private final ChemicalNose chemical;
    private final Map<Object, ControlLoop> loops = new LinkedHashMap<>();
    private ControlLoop[] loopOrder = new ControlLoop[0];
    private String disabledBy;

    /** Used by {@link net.smc.sim.world.SimWorld#addRobot}; {@code index} numbers the robot's noise stream. */
    public SimRobot(RobotGround ground, String id, int index, KoalaSpec spec, Arena.Start start) {
        this.ground = Objects.requireNonNull(ground, "ground");
        this.id = Objects.requireNonNull(id, "id");
        this.index = index;
        this.spec = Objects.requireNonNull(spec, "spec");
        body = new Body();
        BodyFixture fixture = body.addFixture(Geometry.createRectangle(spec.length(), spec.width()));
        fixture.setDensity(spec.mass() / (spec.length() * spec.width()));
        fixture.setFriction(0.3);
        fixture.setRestitution(0);
        body.setMass(MassType.NORMAL);
        body.rotateAboutCenter(start.heading());
        body.translate(start.x(), start.y());
        body.setUserData(new Thing(Thing.Kind.ROBOT, id));
        motors = new Motors(this);
        odometry = new WheelOdometry(new Pose(start.x(), start.y(), start.heading()));
        battery = new PowerCell(spec);
        proximity = new InfraredRing(this);
        camera = new ForwardCamera(this);
        chemical = new ChemicalNose(this);
    }

    @Override
    public String id() {
        return id;
    }

    @Override
    public boolean has(Device device) {
        return DEVICES.contains(device);
    }

    private static final Set<Device> DEVICES = EnumSet.allOf(Device.class);

    @Override
    public Drive drive() {
        return motors;
    }

    @Override
    public Odometry odometry() {
        return odometry;
    }

    @Override
    public ProximitySensors proximity() {
        return proximity;
    }

    @Override
    public Camera camera() {
        return camera;
    }

    @Override
    public ChemicalSensor chemical() {
        return chemical;
    }

    @Override
    public Battery battery() {
        return battery;
    }

    @Override
    public Radio radio() {
        return ground.radio(id);
    }

    @Override
    public void control(Object owner, ControlLoop loop) {
        Objects.requireNonNull(owner, "owner");
        if (loop == null) {
            loops.remove(owner);
        } else {
            loops.put(owner, loop);
        }
        loopOrder = loops.values().toArray(new ControlLoop[0]);
    }

    /** The true pose (what odometry estimates), heading in (-pi, pi]. */
    public Pose pose() {
        return new Pose(body.getTransform().getTranslationX(), body.getTransform().getTranslationY(),
                body.getTransform().getRotationAngle());
    }

    /** The body centre's x, m (cheaper than {@link #pose()}, which works out the heading). */
    public double x() {
        return body.getTransform().getTranslationX();
    }

    /** The body centre's y, m. */
    public double y() {
        return body.getTransform().getTranslationY();
    }

    public KoalaSpec spec() {
        return spec;
    }

    /** The robot's body in the physics world (for renderers and checks; do not move it). */
    public Body body() {
        return body;
    }

    /** Whether its drive and radio are out (a hazard or a flat battery). */
    public boolean disabled() {
        return disabledBy != null;
    }

    /** What disabled it ({@code hazard:ID}, {@code battery}, or a cause given to {@link #disable}), or null. */
    public String disabledBy() {
        return disabledBy;
    }

    /**
     * A position fix from outside the robot (positioning beacons, say): the odometry's estimate
     * becomes the true pose, and dead reckoning goes on from there.
     */
    public void positionFix() {
        odometry.fix(pose());
    }

    /** Disables the drive and the radio from now on (a fault injected by a scenario). */
    public void disable(String cause) {
        if (disabledBy == null) {
            disableNow(Objects.requireNonNull(cause, "cause"));
        }
    }

    private String disableNow(String cause) {
        disabledBy = cause;
        ground.radioOff(this);
        return cause;
    }

    /** Whether the radio is on: not disabled. */
    public boolean radioOn() {
        return disabledBy == null;
    }

    RobotGround ground() {
        return ground;
    }

    /** The noise stream of this robot. */
    long stream() {
        return index;
    }

    /** Step 1 of a world step: the control loops, in registration order. */
    public void runControl(double time, double dt) {
        for (ControlLoop loop : loopOrder) {
            loop.step(time, dt);
        }
    }

    /** Step 2: ramp the wheels and set the body's velocities. */
    public void applyDrive(double dt) {
        motors.ramp(dt, motors.working());
        double heading = body.getTransform().getRotationAngle();
        double v = (motors.left() + motors.right()) / 2;
        body.setLinearVelocity(v * Math.cos(heading), v * Math.sin(heading));
        body.setAngularVelocity((motors.right() - motors.left()) / spec.wheelBase());
    }

    /**
     * Step 3, after the physics: odometry, battery and hazards.
     *
     * @return what disabled the robot in this step, or null
     */
    public String afterStep(double dt) {
        double noise = spec.odometryNoise();
        double left = motors.left() * (1 + noise * ground.gaussian(index, Channels.ODOMETRY_LEFT));
        double right = motors.right() * (1 + noise * ground.gaussian(index, Channels.ODOMETRY_RIGHT));
        odometry.advance(left, right, spec.wheelBase(), dt);
        battery.drain(dt, (Math.abs(motors.left()) + Math.abs(motors.right())) / (2 * spec.maxSpeed()));
        if (disabledBy != null) {
            return null;
        }
        Pose p = pose();
        for (Hazard hazard : ground.arena().hazards()) {
            if (hazard.disables() && p.distanceTo(hazard.x(), hazard.y()) <= hazard.effect()) {
                return disableNow("hazard:" + hazard.id());
            }
        }
        if (battery.flat()) {
            return disableNow("battery");
        }
        return null;
    }

    @Override
    public String toString() {
        return "robot " + id;
    }

    /** Noise channel numbers, one per source in a step, so that draws never collide. */
    static final class Channels {
        static final int ODOMETRY_LEFT = 0;
        static final int ODOMETRY_RIGHT = 1;
        static final int INFRARED = 10;        // + sensor index
        static final int CAMERA = 1_000;       // + 2 * candidate index (+1: bearing)

        private Channels() {
        }
    }
}
