package net.smc.policy.stdlib;

import net.smc.policy.api.Managed;
import net.smc.policy.api.Op;
import net.smc.policy.api.PonderError;

/**
 * Ponder2's semaphore, in a cell that runs one thing at a time: {@code wait} takes a permit when
 * there is one; when there is none it fails with an error instead of blocking, since nothing else
 * in the cell could run to release it (the cell would hang for ever). {@code release} adds a
 * permit; {@code permits} (extension) answers how many there are.
 */
@Managed("Semaphore")
final class Semaphore {
    private long permits;

    @Op("create")
    Semaphore() {
        this(0);
    }

    @Op("create:")
    Semaphore(long initial) {
        if (initial < 0) {
            throw new PonderError("a semaphore starts with 0 or more permits, got " + initial);
        }
        this.permits = initial;
    }

    @Op("wait")
    void acquire() {
        if (permits == 0) {
            throw new PonderError("Semaphore wait: no permit available, and waiting would block the cell for ever");
        }
        permits--;
    }

    @Op("release")
    void release() {
        permits++;
    }

    @Op("permits")
    long permits() {
        return permits;
    }
}
