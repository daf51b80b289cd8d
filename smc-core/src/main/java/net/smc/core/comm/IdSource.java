package net.smc.core.comm;

import net.smc.core.transport.Clock;

/**
 * Message ids of one cell: strictly increasing, so that {@code (vehicle id, message id)} names one
 * message. The first id is the clock at start shifted left by 16 bits (65,536 ids per millisecond
 * of up-time), so a cell that restarts under the same vehicle id continues above the ids it used
 * before, and its new messages are not taken by its peers for duplicates of old ones.
 */
final class IdSource {
    private long next;

    IdSource(Clock clock) {
        next = (Math.max(0, clock.nowMillis()) << 16) + 1;
    }

    long next() {
        return next++;
    }
}
