package net.smc.core.transport.sim;

import net.smc.core.transport.Address;

/**
 * What each datagram costs the CPU of the node that sends or receives it, in microseconds of that
 * node's time: the hook through which a simulation charges each cell for its own work (encoding,
 * signing, verifying, parsing and loading policies ...), so that a cell that handles many inputs
 * becomes the bottleneck it would be on a vehicle.
 *
 * <p>The {@link InMemoryNetwork} keeps, per node, the time its CPU is busy until. A datagram that
 * arrives waits in the node's inbox until the CPU is free, then occupies it for
 * {@link #receiveMicros}; the cell handles it when that time has passed. A datagram the node sends
 * occupies its CPU for {@link #sendMicros} and leaves when that work is done (and, with a
 * bandwidth, when the radio has transmitted it). Timers are not delayed: a cell's periodic work
 * runs on time, and what it sends is charged.
 *
 * <p>Asked on the simulation's thread, once per datagram (a broadcast is one send, and one receive
 * at each node that gets a copy). Must be deterministic (no wall clock) for a run to replay.
 */
public interface CpuModel {

    /** The default: nothing costs anything, and datagrams are handled as they arrive. */
    CpuModel FREE = new CpuModel() {
        @Override
        public long sendMicros(Address at, Address to, byte[] data) {
            return 0;
        }

        @Override
        public long receiveMicros(Address at, Address from, byte[] data, boolean broadcast) {
            return 0;
        }
    };

    /**
     * The CPU time node {@code at} spends sending {@code data}.
     *
     * @param to the destination, or null for a broadcast
     * @return microseconds, 0 or more
     */
    long sendMicros(Address at, Address to, byte[] data);

    /**
     * The CPU time node {@code at} spends on a datagram from {@code from} before its cell acts on it.
     *
     * @param broadcast whether the datagram was broadcast
     * @return microseconds, 0 or more
     */
    long receiveMicros(Address at, Address from, byte[] data, boolean broadcast);

    /**
     * The bytes node {@code at}'s radio transmits for {@code data}, asked right after
     * {@link #sendMicros} for the same datagram when the network has a bandwidth: by default the
     * datagram's length. A model of traffic the simulation does not carry byte for byte (the
     * envelope a real security layer puts round each datagram, the handshakes it runs beside them)
     * answers what the real radio would send.
     *
     * @param to the destination, or null for a broadcast
     * @return bytes, 0 or more
     */
    default long airBytes(Address at, Address to, byte[] data) {
        return data.length;
    }
}
