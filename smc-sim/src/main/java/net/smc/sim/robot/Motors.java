package net.smc.sim.robot;

import net.smc.sim.hardware.Drive;

/** The two motors: commanded wheel speeds, clamped, and the actual speeds ramping towards them. */
final class Motors implements Drive {
    private final SimRobot robot;
    private double commandLeft;
    private double commandRight;
    private double left;
    private double right;

    Motors(SimRobot robot) {
        this.robot = robot;
    }

    @Override
    public void setWheelSpeeds(double left, double right) {
        if (!Double.isFinite(left) || !Double.isFinite(right)) {
            throw new IllegalArgumentException("wheel speeds (" + left + ", " + right + ") must be finite numbers");
        }
        double max = maxSpeed();
        commandLeft = Math.max(-max, Math.min(max, left));
        commandRight = Math.max(-max, Math.min(max, right));
    }

    @Override
    public double maxSpeed() {
        return robot.spec().maxSpeed();
    }

    @Override
    public double wheelBase() {
        return robot.spec().wheelBase();
    }

    @Override
    public boolean working() {
        return !robot.disabled() && !robot.battery().flat();
    }

    /** The left wheel's actual speed, m/s. */
    double left() {
        return left;
    }

    double right() {
        return right;
    }

    /** Moves the actual speeds towards the commands within the acceleration limit; a dead drive stops at once. */
    void ramp(double dt, boolean working) {
        if (!working) {
            left = 0;
            right = 0;
            return;
        }
        double step = robot.spec().maxAcceleration() * dt;
        left += Math.max(-step, Math.min(step, commandLeft - left));
        right += Math.max(-step, Math.min(step, commandRight - right));
    }
}
