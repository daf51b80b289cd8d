package net.smc.sim.hardware;

/** A ring of infrared proximity sensors around the body. */
public interface ProximitySensors {

    /** How many sensors there are. */
    int count();

    /** Sensor {@code i}'s direction, radians relative to the robot's heading. */
    double angle(int i);

    /** The sensors' range, m. */
    double range();

    /**
     * The distances the sensors read now, m, from the body's edge; {@link #range()} where nothing
     * is in range. One entry per sensor, in sensor order; a fresh array each call.
     */
    double[] read();
}
