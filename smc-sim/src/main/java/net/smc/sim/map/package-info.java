/**
 * The map a robot builds of the arena: {@link net.smc.sim.map.OccupancyGrid}, a grid of unknown,
 * free and occupied cells filled from range readings and merged across robots, and
 * {@link net.smc.sim.map.PathPlanner}, A* on that grid around obstacles and avoided
 * {@link net.smc.sim.map.Zone}s. Units are metres; nothing here knows whether the readings are
 * simulated.
 */
package net.smc.sim.map;
