package net.smc.sim.task;

import net.smc.sim.hardware.Pose;

/**
 * Tells a robot that drives but does not move: wedged on a corner, say. It is stalled once it has
 * stayed within a distance ({@link #MOVED} unless told otherwise) of where it was first seen for
 * more than the given time. A long watch over a larger distance tells a robot that creeps without
 * getting anywhere: pushing against something that does not give, its position jittering by a few
 * centimetres, which a short watch takes for moves.
 */
final class StallWatch {
    /** Less than this, in metres, is not a move. */
    static final double MOVED = 0.05;

    private final double seconds;
    private final double moved;
    private double x = Double.NaN;
    private double y;
    private double since;

    StallWatch(double seconds) {
        this(seconds, MOVED);
    }

    /** A watch that takes less than {@code moved} metres for no move. */
    StallWatch(double seconds, double moved) {
        if (!(seconds > 0) || !(moved > 0) || !Double.isFinite(seconds) || !Double.isFinite(moved)) {
            throw new IllegalArgumentException("StallWatch: seconds " + seconds + " and moved " + moved
                    + " must be positive numbers");
        }
        this.seconds = seconds;
        this.moved = moved;
    }

    /** Whether the robot, at {@code pose} at {@code time}, has been stalled; a move starts the watch again. */
    boolean stalled(double time, Pose pose) {
        if (Double.isNaN(x) || Math.hypot(pose.x() - x, pose.y() - y) > moved) {
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
