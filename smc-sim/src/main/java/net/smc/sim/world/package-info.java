/**
 * The simulated 2-D world: arenas read from world files ({@link net.smc.sim.world.ArenaReader},
 * {@code missions/worlds/}), built into a dyn4j world and stepped at a fixed period on the
 * simulation's virtual clock ({@link net.smc.sim.world.SimWorld}, the place to start), with
 * seeded, counter-based noise ({@link net.smc.sim.world.Noise}) and step listeners for renderers
 * and recorders ({@link net.smc.sim.world.WorldStepListener}). Units: metres, seconds, radians.
 */
package net.smc.sim.world;
