package net.smc.core.transport.sim;

import net.smc.core.transport.Address;

/**
 * Watches every datagram copy the {@link InMemoryNetwork} delivers or drops: for traces,
 * invariant checks and pictures of the run. Both methods fire on the simulation's thread;
 * {@code data} is the copy's payload and must be neither modified nor kept.
 */
public interface NetworkObserver {

    /** Fires when a copy reaches its destination, just before the destination's receiver gets it. */
    default void delivered(long atMillis, Address from, Address to, byte[] data) {
    }

    /**
     * Fires when a copy is dropped: at send time for {@link DropReason#LOSS}, {@link DropReason#PARTITION},
     * {@link DropReason#RADIO} and {@link DropReason#SENDER_DOWN}; at arrival time for
     * {@link DropReason#RECEIVER_DOWN} and {@link DropReason#NO_RECEIVER}.
     */
    default void dropped(long atMillis, Address from, Address to, DropReason reason, byte[] data) {
    }
}
