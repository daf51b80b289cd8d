package net.smc.core.comm;

import java.util.ArrayDeque;
import java.util.HashSet;
import java.util.Set;

/**
 * The receiver's memory of the critical messages it delivered, so that a retransmission (its Ack
 * was lost) or a copy the network duplicated is acknowledged again but not delivered again.
 *
 * <p>A message is named by {@code (sender vehicle id, message id)}, unique by the envelope's
 * contract. Entries live for a fixed time, which {@link SenderSettings} checks to outlast every
 * retransmission, and their number is capped so that a flood cannot exhaust memory; an entry
 * pushed out early by the cap is counted ({@link #evictedEarly()}), because a late copy of it
 * would be delivered twice: a non-zero count says the cap is too small for the traffic.
 */
final class DuplicateWindow {
    private record Key(String sender, long id) {
    }

    private record Stamp(Key key, long expiresMillis) {
    }

    private final long windowMillis;
    private final int maxEntries;
    private final Set<Key> seen = new HashSet<>();
    /** Entries in arrival order, which is expiry order because the clock never goes back. */
    private final ArrayDeque<Stamp> order = new ArrayDeque<>();
    private long expired;
    private long evictedEarly;

    DuplicateWindow(long windowMillis, int maxEntries) {
        this.windowMillis = windowMillis;
        this.maxEntries = maxEntries;
    }

    /**
     * Records message {@code (sender, id)} received at {@code nowMillis}.
     *
     * @return true the first time within the window, false for a duplicate
     */
    boolean firstSeen(String sender, long id, long nowMillis) {
        expire(nowMillis);
        Key key = new Key(sender, id);
        if (!seen.add(key)) {
            return false;
        }
        order.addLast(new Stamp(key, nowMillis + windowMillis));
        if (order.size() > maxEntries) {
            seen.remove(order.removeFirst().key);
            evictedEarly++;
        }
        return true;
    }

    /** Messages remembered now. */
    int size() {
        return seen.size();
    }

    /** Entries forgotten because their time was up. */
    long expired() {
        return expired;
    }

    /** Entries forgotten before their time because the window was full. */
    long evictedEarly() {
        return evictedEarly;
    }

    private void expire(long nowMillis) {
        for (Stamp s = order.peekFirst(); s != null && s.expiresMillis <= nowMillis; s = order.peekFirst()) {
            order.removeFirst();
            seen.remove(s.key);
            expired++;
        }
    }
}
