package net.smc.sim.hardware;

/**
 * One robot's devices, as a task sees them. Every device is always present; a robot without
 * one (no camera, say) answers with an empty reading and says so through {@link #has(Device)}.
 */
public interface RobotHardware {

    /** The devices a robot may carry; they map onto the capability description's resources. */
    enum Device { DRIVE, ODOMETRY, PROXIMITY, CAMERA, CHEMICAL, BATTERY, RADIO }

    /** The robot's id (its vehicle's id). */
    String id();

    boolean has(Device device);

    Drive drive();

    Odometry odometry();

    ProximitySensors proximity();

    Camera camera();

    ChemicalSensor chemical();

    Battery battery();

    Radio radio();

    /**
     * Registers a controller called once per control period (the world's step), on the cell's
     * thread, with the mission time in seconds. Replaces any previous controller of the same
     * owner; {@code null} removes it.
     */
    void control(Object owner, ControlLoop loop);
}
