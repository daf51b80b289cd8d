package net.smc.sim.world;

import net.smc.sim.robot.SimRobot;

/**
 * Observes a {@link SimWorld} step by step: renderers, recorders and tests. Called on the
 * simulation's thread; a listener must not step the world itself. Reading sensors from a listener
 * does not change the run (see {@link Noise}).
 */
public interface WorldStepListener {

    /**
     * Fires once per step, after the control loops ran, the physics moved every body and the
     * robots' odometry, batteries and hazard checks were updated.
     */
    default void stepped(SimWorld world) {
    }

    /**
     * Fires when a robot loses its drive and radio (a disabling hazard's radius of effect, a flat
     * battery), during the step that disables it and before {@link #stepped}.
     *
     * @param cause {@code hazard:ID} or {@code battery}
     */
    default void disabled(SimWorld world, SimRobot robot, String cause) {
    }
}
