package net.smc.sim.hardware;

/** A task's control step, called once per control period. */
@FunctionalInterface
public interface ControlLoop {

    /**
     * @param time the mission time, seconds
     * @param dt   the time since the previous call, seconds
     */
    void step(double time, double dt);
}
