package net.smc.sim.experiment;

import net.smc.core.cell.Scheme;

/**
 * One run of the set-up time experiment.
 *
 * @param roles        roles (seats) of the mission, the commander's included
 * @param scheme       distributed or centralised
 * @param transport    {@code sim} (the simulated radio network) or {@code udp} (Netty UDP on loopback)
 * @param run          the run's number, from 1
 * @param setupMillis  the commander's start to the last role started (simulated ms, or wall ms on UDP);
 *                     -1 when not every role started within the limit
 * @param messages     datagrams sent until then (a broadcast once); -1 when not counted
 * @param bytes        bytes of those datagrams; -1 when not counted
 * @param busiestCpuMillis the CPU time charged to the busiest cell until then; on UDP the CPU time its
 *                     thread used, measured, until the run was seen to end
 * @param started      roles started (of {@code roles - 1}: the commander's is not assigned)
 * @param undelivered  critical messages the cells gave up on (no Ack after every retransmission) by
 *                     the run's end: a radio so backed up that a peer's Acks come too late
 */
public record SetupResult(int roles, Scheme scheme, String transport, int run, double setupMillis, long messages,
                          long bytes, double busiestCpuMillis, int started, long undelivered) {

    /** Whether every role started. */
    public boolean complete() {
        return setupMillis >= 0;
    }
}
