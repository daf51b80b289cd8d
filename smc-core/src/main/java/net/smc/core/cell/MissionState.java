package net.smc.core.cell;

/** The acting commander's view of its team against the mission's configurations. */
public enum MissionState {
    /** Some role has fewer holders than the minimal configuration needs: the mission waits. */
    FORMING,
    /** The minimal configuration is filled: the mission runs, and grows as vehicles join. */
    RUNNING,
    /** Every seat is held by a vehicle of its own: the reasonably-optimal configuration. */
    OPTIMAL
}
