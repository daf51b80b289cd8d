package net.smc.core.security;

import java.util.Arrays;

/**
 * Remembers the most recent counters accepted from one sender, so that a repeat is refused while a
 * message the network re-ordered still passes. Counters need not be dense (a sender's counter
 * follows its clock, see {@code SecureEndpoint}), so this keeps the counters themselves, sorted,
 * rather than the bitmap of IPsec and DTLS: the newest {@code capacity} accepted, plus a floor
 * (the newest one forgotten) at or below which everything is refused.
 *
 * <p>{@link #isFresh} only looks; {@link #mark} changes the state, and is called only after every
 * other check passed, so that a refused message leaves no trace.
 */
final class ReplayWindow {
    private final long[] seen;
    private int size;
    private long floor = Long.MIN_VALUE;
    private long newestTimestampMillis = Long.MIN_VALUE;

    ReplayWindow(int capacity) {
        this.seen = new long[capacity];
    }

    /** Whether {@code counter} has not been accepted before and is newer than everything forgotten. */
    boolean isFresh(long counter) {
        if (size == 0 || counter > seen[size - 1]) {
            return counter > floor;   // newer than every counter kept: the usual case, no search
        }
        return counter > floor && Arrays.binarySearch(seen, 0, size, counter) < 0;
    }

    /** Records {@code counter} (which must be fresh), sent at {@code timestampMillis}; forgets the oldest when full. */
    void mark(long counter, long timestampMillis) {
        newestTimestampMillis = Math.max(newestTimestampMillis, timestampMillis);
        int at = size == 0 || counter > seen[size - 1] ? size : -Arrays.binarySearch(seen, 0, size, counter) - 1;
        if (size == seen.length) {
            if (at == 0) {
                floor = counter;   // older than everything kept: remembering it would forget a newer one
                return;
            }
            floor = seen[0];
            System.arraycopy(seen, 1, seen, 0, at - 1);
            seen[at - 1] = counter;
        } else {
            System.arraycopy(seen, at, seen, at + 1, size - at);
            seen[at] = counter;
            size++;
        }
    }

    /** The newest timestamp among the accepted messages; a window whose newest is stale may be dropped. */
    long newestTimestampMillis() {
        return newestTimestampMillis;
    }

    /** The floor and the counters kept, oldest first: for traces and tests. */
    @Override
    public String toString() {
        return "ReplayWindow[floor=" + floor + ", seen=" + Arrays.toString(Arrays.copyOf(seen, size)) + "]";
    }
}
