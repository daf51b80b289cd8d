package net.smc.sim.task;

import java.util.Objects;
import net.smc.core.task.Task;
import net.smc.sim.hardware.RobotHardware;

/**
 * A task that works a robot's hardware: while it runs, {@link #step(double, double)} is its
 * control loop, registered with the robot on start and removed on stop (the robot stops too).
 */
public abstract class RobotTask extends Task {
    protected final RobotHardware hardware;

    protected RobotTask(RobotHardware hardware) {
        this.hardware = Objects.requireNonNull(hardware, "hardware");
    }

    /**
     * The least clearance a path may keep from an occupied cell's centre: the body's half-width
     * and 5 cm, for when no path keeps the task's own (a doorway narrowed on the map by its jambs).
     */
    final double narrowClearance() {
        return hardware.drive().wheelBase() / 2 + 0.05;
    }

    @Override
    protected void onStart() {
        hardware.control(this, this::step);
    }

    @Override
    protected void onStop() {
        hardware.control(this, null);
        if (drives()) {
            hardware.drive().stop();
        }
    }

    /** Whether this task moves the robot (so stopping it stops the wheels). */
    protected boolean drives() {
        return false;
    }

    /** One control period. */
    protected abstract void step(double time, double dt);
}
