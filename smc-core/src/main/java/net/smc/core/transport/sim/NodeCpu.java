package net.smc.core.transport.sim;

import java.util.ArrayDeque;
import java.util.Deque;

import net.smc.core.transport.Address;

/**
 * One node's CPU and radio transmitter under a {@link CpuModel}: the times (in microseconds of
 * virtual time) each is busy until, the datagrams waiting for the CPU, and the CPU time charged.
 */
final class NodeCpu {
    /** A datagram that has arrived and waits for the CPU. */
    record Waiting(Address from, byte[] data, boolean broadcast, long arrivedMicros) {
    }

    final Deque<Waiting> inbox = new ArrayDeque<>();
    long busyUntilMicros;
    long transmitterFreeMicros;
    /** When the last datagram this node sent leaves it (its CPU work done and, with a bandwidth, its last bit out). */
    long lastDepartureMicros;
    long chargedMicros;
    /** Whether a datagram of the inbox is being worked on or is scheduled to be. */
    boolean draining;

    /** Occupies the CPU for {@code micros} from {@code fromMicros} or when it is free; returns when that ends. */
    long charge(long fromMicros, long micros) {
        if (micros < 0) {
            throw new IllegalArgumentException("a CPU cost of " + micros + " us is negative; it must be 0 or more");
        }
        busyUntilMicros = Math.max(fromMicros, busyUntilMicros) + micros;
        chargedMicros += micros;
        return busyUntilMicros;
    }

    /** Transmits {@code bytes} once the CPU work ends at {@code readyMicros}; returns when the last bit is out. */
    long transmit(long readyMicros, long bytes, long bytesPerSecond) {
        if (bytesPerSecond <= 0) {
            return readyMicros;
        }
        long start = Math.max(readyMicros, transmitterFreeMicros);
        transmitterFreeMicros = start + (bytes * 1_000_000L + bytesPerSecond - 1) / bytesPerSecond;
        return transmitterFreeMicros;
    }
}
