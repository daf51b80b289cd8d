package net.smc.core.router;

import java.util.Arrays;
import net.smc.core.message.MessageType;

/**
 * Everything the router holds about packets from one source, found with one lookup: who
 * registered for all of its packets ({@code all}), who registered for one type from it
 * ({@code pairs}, by type), and its row of the exclusion table ({@code excluded}, by type): who
 * de-registered that type from this source while an aggregate registration (for the whole type, or
 * for the whole source) still covers it. Arrays are copy-on-write {@link CopyOnWriteBits}.
 */
final class SourceRow {
    private static final int TYPES = MessageType.values().length;

    long[] all = CopyOnWriteBits.EMPTY;
    final long[][] pairs = emptyRow();
    final long[][] excluded = emptyRow();

    private static long[][] emptyRow() {
        long[][] row = new long[TYPES][];
        Arrays.fill(row, CopyOnWriteBits.EMPTY);
        return row;
    }

    boolean isEmpty() {
        if (!CopyOnWriteBits.isEmpty(all)) {
            return false;
        }
        for (int t = 0; t < TYPES; t++) {
            if (!CopyOnWriteBits.isEmpty(pairs[t]) || !CopyOnWriteBits.isEmpty(excluded[t])) {
                return false;
            }
        }
        return true;
    }
}
