package net.smc.sim.task;

import net.smc.sim.hardware.Pose;

/**
 * Tells a robot that drives but does not move: wedged on a corner, say. It is stalled once it has
 * stayed within {@link #MOVED} of where it was first seen for more than the given time.
 */
final class StallWatch {
    /** Less than this, in metres, is not a move. */
    static final double MOVED = 0.05;

    private final double seconds;
    private double x = Double.NaN;
    private double y;
    private double since;

    StallWatch(double seconds) {
        this.seconds = seconds;
    }

    /** Whether the robot, at {@code pose} at {@code time}, has been stalled; a move starts the watch again. */
    boolean stalled(double time, Pose pose) {
        if (Double.isNaN(x) || Math.hypot(pose.x() - x, pose.y() - y) > MOVED) {
            x = pose.x();
            y = pose.y();
            since = time;
            return false;
        }
        return time - since > seconds;
    }

    /** Forgets where the robot was: the next pose starts the watch. */
    void reset() {
        x = Double.NaN;
    }
}
