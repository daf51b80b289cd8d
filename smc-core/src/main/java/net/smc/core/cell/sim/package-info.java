/**
 * Whole teams in one JVM on the in-memory network and a virtual clock: {@link
 * net.smc.core.cell.sim.TeamSimulation} runs them, {@link net.smc.core.cell.sim.TeamInvariants}
 * checks them after every step, {@link net.smc.core.cell.sim.FaultSchedule} drives one seeded run of
 * faults. A failing run throws {@link net.smc.core.cell.sim.InvariantViolation} with its seed and
 * trace; the same seed replays it exactly.
 */
package net.smc.core.cell.sim;
