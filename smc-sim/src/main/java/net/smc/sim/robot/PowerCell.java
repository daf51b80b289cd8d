package net.smc.sim.robot;

import net.smc.sim.hardware.Battery;

/** A battery drained at a rate between its idle and its full-speed rate, by how hard the wheels turn. */
final class PowerCell implements Battery {
    private final double idleRate;
    private final double movingRate;
    private double level = 1;

    PowerCell(KoalaSpec spec) {
        idleRate = 1 / spec.enduranceIdle();
        movingRate = 1 / spec.enduranceMoving();
    }

    @Override
    public double level() {
        return level;
    }

    /** @param effort mean wheel speed as a fraction of top speed, 0..1 */
    void drain(double dt, double effort) {
        level = Math.max(0, level - dt * (idleRate + (movingRate - idleRate) * Math.min(1, effort)));
    }
}
