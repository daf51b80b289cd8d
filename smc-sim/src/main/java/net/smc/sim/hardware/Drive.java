package net.smc.sim.hardware;

/** A differential drive: two wheel speeds, limited in speed and acceleration by the hardware. */
public interface Drive {

    /**
     * Asks for wheel speeds in m/s (positive: forward). The hardware clamps them to
     * {@link #maxSpeed()} and ramps to them within its acceleration limit; it never jumps.
     */
    void setWheelSpeeds(double left, double right);

    /** Stops both wheels (as fast as the acceleration limit allows). */
    default void stop() {
        setWheelSpeeds(0, 0);
    }

    /** The top wheel speed, m/s. */
    double maxSpeed();

    /** The distance between the wheels, m. */
    double wheelBase();

    /** Whether the drive still moves the robot (false once disabled: flat battery, destroyed). */
    boolean working();
}
