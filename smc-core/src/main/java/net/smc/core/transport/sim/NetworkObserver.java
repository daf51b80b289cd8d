package net.smc.core.transport.sim;

import net.smc.core.transport.Address;

/**
 * Watches every datagram the {@link InMemoryNetwork}'s nodes send and every copy it delivers or
 * drops: for traces, invariant checks, traffic counts and pictures of the run. The methods fire on
 * the simulation's thread; {@code data} is the datagram's payload and must be neither modified nor
 * kept. Watching changes nothing in the run: no event is scheduled and nothing is drawn for it.
 */
public interface NetworkObserver {

    /**
     * Fires once for each datagram a live node sends (a broadcast once, with {@code to} null), before
     * the network decides the fate of its copies. A crashed node's sends do not fire it (they are
     * dropped as {@link DropReason#SENDER_DOWN}).
     */
    default void sent(long atMillis, Address from, Address to, byte[] data) {
    }

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
