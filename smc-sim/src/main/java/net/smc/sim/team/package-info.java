/**
 * Whole teams in one JVM on the in-memory network and a virtual clock: {@link
 * net.smc.sim.team.TeamSimulation} runs them, {@link net.smc.sim.team.TeamInvariants}
 * checks them after every step, {@link net.smc.sim.team.FaultSchedule} drives one seeded run of
 * faults. A failing run throws {@link net.smc.sim.team.InvariantViolation} with its seed and
 * trace; the same seed replays it exactly.
 */
package net.smc.sim.team;
