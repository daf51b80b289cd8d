package net.smc.sim.task;

import java.util.Objects;
import net.smc.sim.hardware.RobotHardware;
import net.smc.sim.map.OccupancyGrid;

/**
 * What a task is made with on one robot: its hardware, and the map that robot's tasks share (the
 * Explorer fills it, the Navigator plans on it, the Aggregator merges into it).
 */
public record TaskContext(RobotHardware hardware, OccupancyGrid map) {
    public TaskContext {
        Objects.requireNonNull(hardware, "hardware");
        Objects.requireNonNull(map, "map");
    }
}
