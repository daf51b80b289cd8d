package net.smc.sim.hardware;

/** The robot's battery: drains with motion (and slowly at rest). */
public interface Battery {

    /** The charge left, 0..1. */
    double level();

    /** Whether the battery is flat (the drive then stops working). */
    default boolean flat() {
        return level() <= 0;
    }
}
