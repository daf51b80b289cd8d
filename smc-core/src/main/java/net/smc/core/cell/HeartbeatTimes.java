package net.smc.core.cell;

/**
 * When this cell sent its recent heartbeats, by their {@linkplain net.smc.core.message.Echo#tagOf
 * tags}: the last {@value #CAPACITY}, oldest forgotten first, in two arrays used as a ring (no boxing,
 * nothing allocated per heartbeat). An echo names the newest heartbeat most of the time, so a look-up
 * searches from the newest back. Tags are 1 or more; 0 marks a free place.
 */
final class HeartbeatTimes {
    static final int CAPACITY = 64;
    /** What {@link #sentAt} answers for a tag not held. */
    static final long NONE = Long.MIN_VALUE;

    private final long[] tags = new long[CAPACITY];
    private final long[] millis = new long[CAPACITY];
    /** Where the next new tag goes: the newest is just before it. */
    private int next;
    private int size;

    /** Records that the heartbeat of {@code tag} was sent at {@code at}; a tag already held keeps its place and takes the new time. */
    void put(long tag, long at) {
        int i = indexOf(tag);
        if (i >= 0) {
            millis[i] = at;
            return;
        }
        tags[next] = tag;
        millis[next] = at;
        next = (next + 1) % CAPACITY;
        size = Math.min(size + 1, CAPACITY);
    }

    /** When the heartbeat of {@code tag} was sent, or {@link #NONE} if it is not among the last {@value #CAPACITY}. */
    long sentAt(long tag) {
        int i = indexOf(tag);
        return i < 0 ? NONE : millis[i];
    }

    private int indexOf(long tag) {
        int i = next;
        for (int k = 0; k < size; k++) {
            i = i == 0 ? CAPACITY - 1 : i - 1;
            if (tags[i] == tag) {
                return i;
            }
        }
        return -1;
    }
}
