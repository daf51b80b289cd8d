/**
 * The data of a simulated world: an immutable {@link net.smc.sim.arena.Arena} (walls, doors,
 * obstacles, hazards, targets, stations, start positions) read and checked from a world file by
 * {@link net.smc.sim.arena.ArenaReader} (the place to start; {@code missions/worlds/}, every error
 * as {@code FILE:LINE:COL: <element>: message}), and the {@link net.smc.sim.arena.Thing} every
 * body of the physics world is tagged with. Both the world that steps robots
 * ({@code net.smc.sim.world}) and the robots ({@code net.smc.sim.robot}) use it. Units: metres,
 * radians.
 *
 * <pre>{@code
 * Arena rescue = ArenaReader.read(Path.of("missions/worlds/rescue.xml"));
 * SimWorld world = SimWorld.builder(rescue, scheduler).seed(7).build();
 * }</pre>
 */
package net.smc.sim.arena;
