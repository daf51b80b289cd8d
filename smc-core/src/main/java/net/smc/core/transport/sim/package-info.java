/**
 * Simulation of the network a team talks over, on virtual time:
 * {@link net.smc.core.transport.sim.SimulationScheduler} (the clock and the one deterministic
 * scheduler that drives every simulated cell, the network and the world) and
 * {@link net.smc.core.transport.sim.InMemoryNetwork} (endpoints with per-link latency, jitter,
 * loss, duplication, re-ordering, partitions, crashes and a {@link net.smc.core.transport.sim.RadioModel}
 * hook for the world's radio ranges). Same seed, same run, to the byte: this is what lets protocol
 * tests run whole teams under faults and check invariants after every step.
 *
 * <p>Everything here is single-threaded. See <a href="../doc-files/transport.md">the transport design note</a>.
 */
package net.smc.core.transport.sim;
