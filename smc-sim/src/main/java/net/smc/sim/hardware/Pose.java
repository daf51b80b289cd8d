package net.smc.sim.hardware;

/**
 * A position and heading on the plane.
 *
 * @param x       metres
 * @param y       metres
 * @param heading radians, counter-clockwise from +x, in (-pi, pi]
 */
public record Pose(double x, double y, double heading) {

    public double distanceTo(double px, double py) {
        return Math.hypot(px - x, py - y);
    }
}
