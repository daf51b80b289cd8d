package net.smc.core.transport.sim;

import net.smc.core.transport.Address;

/**
 * Decides whether a radio signal gets from one node to another: the hook through which the
 * simulated world (robot positions, range, obstacles) shapes the {@link InMemoryNetwork}.
 * Partitions and link faults apply on top of it.
 */
@FunctionalInterface
public interface RadioModel {

    /** The default: every node hears every other. */
    RadioModel EVERYONE = (from, to) -> true;

    /**
     * Asked once for each datagram copy, when it is sent (unicast, or one per destination of a
     * broadcast), on the simulation's thread. Must be deterministic for a run to replay.
     *
     * @return whether a datagram sent now from {@code from} can reach {@code to}
     */
    boolean reachable(Address from, Address to);
}
