/**
 * The simulated 2-D world: an arena ({@link net.smc.sim.arena.Arena}, read from a world file by
 * {@link net.smc.sim.arena.ArenaReader}) built into a dyn4j world and stepped at a fixed period on
 * the simulation's virtual clock ({@link net.smc.sim.world.SimWorld}, the place to start), with
 * seeded, counter-based noise ({@link net.smc.sim.world.Noise}) and step listeners for renderers
 * and recorders ({@link net.smc.sim.world.WorldStepListener}). The world makes and steps its
 * robots and offers them a {@link net.smc.sim.robot.RobotGround}, and its radio a
 * {@link net.smc.sim.radio.RadioGround}. Units: metres, seconds, radians.
 */
package net.smc.sim.world;
