package net.smc.sim.robot;

import net.smc.sim.hardware.Odometry;
import net.smc.sim.hardware.Pose;

/** Dead reckoning from the wheel speeds the encoders count (noise included by the caller). */
final class WheelOdometry implements Odometry {
    private double x;
    private double y;
    private double heading;
    private double travelled;

    WheelOdometry(Pose start) {
        x = start.x();
        y = start.y();
        heading = start.heading();
    }

    @Override
    public Pose pose() {
        return new Pose(x, y, heading);
    }

    @Override
    public double travelled() {
        return travelled;
    }

    /** Replaces the estimate by a position fix (the distance travelled goes on). */
    void fix(Pose pose) {
        x = pose.x();
        y = pose.y();
        heading = pose.heading();
    }

    /** Integrates one step of wheel speeds {@code left}, {@code right} (m/s) over {@code dt} seconds. */
    void advance(double left, double right, double wheelBase, double dt) {
        double v = (left + right) / 2;
        double turn = (right - left) / wheelBase * dt;
        double mid = heading + turn / 2;
        x += v * Math.cos(mid) * dt;
        y += v * Math.sin(mid) * dt;
        heading = Math.IEEEremainder(heading + turn, 2 * Math.PI);
        if (heading <= -Math.PI) {
            heading += 2 * Math.PI;
        }
        travelled += Math.abs(v) * dt;
    }
}
