package net.smc.sim.hardware;

/** Wheel odometry: the robot's own estimate of where it is, drifting with the wheels' noise. */
public interface Odometry {

    /** The current estimate, in the arena's frame (it starts at the true start pose). */
    Pose pose();

    /** Distance travelled so far by the robot's centre, as the wheels count it, m. */
    double travelled();
}
