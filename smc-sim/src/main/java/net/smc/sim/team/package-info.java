/**
 * Whole teams in one JVM on the in-memory network and a virtual clock: {@link
 * net.smc.sim.team.TeamSimulation} runs them, {@link net.smc.sim.team.TeamInvariants}
 * checks them after every step, {@link net.smc.sim.team.FaultSchedule} drives one seeded run of
 * faults. A failing run throws {@link net.smc.sim.team.InvariantViolation} with its seed and
 * trace; the same seed replays it exactly. A team may live in the dyn4j world ({@link
 * net.smc.sim.team.WorldTeam}): robots and stations carry the cells, the world's radio carries
 * their traffic, and {@link net.smc.sim.team.RadioSignal} passes the soldier's distress call
 * from the wearable computer to whoever hears it. {@link net.smc.sim.team.LiveTeam} runs such a team
 * with its cells on real UDP over loopback and the world stepped on the wall clock; both are a
 * {@link net.smc.sim.team.CellTeam}.
 */
package net.smc.sim.team;
