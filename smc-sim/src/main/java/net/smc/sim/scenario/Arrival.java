package net.smc.sim.scenario;

import java.util.Objects;

import net.smc.sim.team.SimVehicle;

/**
 * One robot's entrance in a {@link ReconnaissanceScenario}: the vehicle, the start position where it
 * waits, and when it is switched on (mission time, ms).
 */
public record Arrival(SimVehicle vehicle, String start, long atMillis) {
    public Arrival {
        Objects.requireNonNull(vehicle, "vehicle");
        Objects.requireNonNull(start, "start");
    }
}
