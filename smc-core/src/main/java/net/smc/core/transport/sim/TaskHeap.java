package net.smc.core.transport.sim;

import java.util.Arrays;

/**
 * The {@link SimulationScheduler}'s queue: a 4-ary min-heap of {@link SimTask}s ordered by due time,
 * then by sequence number. The order is total (sequence numbers are unique), so the tasks come out
 * in exactly the order any correct priority queue would give. Each task's due time and sequence
 * number are kept beside it in arrays of their own, so that sifting compares numbers in a few
 * cache lines instead of visiting every task object on the way; with four children to a node the
 * heap has half the levels of a binary one. Both matter when a large team keeps hundreds of
 * thousands of datagrams in flight.
 */
final class TaskHeap {
    private static final int ARITY = 4;

    private SimTask[] tasks = new SimTask[256];
    private long[] dues = new long[256];
    private long[] sequences = new long[256];
    private int size;

    int size() {
        return size;
    }

    /** The first task, or null when empty. */
    SimTask peek() {
        return size == 0 ? null : tasks[0];
    }

    void add(SimTask task) {
        if (size == tasks.length) {
            int capacity = size * 2;
            tasks = Arrays.copyOf(tasks, capacity);
            dues = Arrays.copyOf(dues, capacity);
            sequences = Arrays.copyOf(sequences, capacity);
        }
        siftUp(size++, task, task.due, task.sequence);
    }

    /** Removes and returns the first task, or null when empty. */
    SimTask poll() {
        if (size == 0) {
            return null;
        }
        SimTask first = tasks[0];
        int last = --size;
        SimTask moved = tasks[last];
        tasks[last] = null;
        if (last > 0) {
            siftDown(0, moved, dues[last], sequences[last]);
        }
        return first;
    }

    /** Drops every cancelled task and restores the heap (linear time). */
    void removeCancelled() {
        int kept = 0;
        for (int i = 0; i < size; i++) {
            if (!tasks[i].isCancelled()) {
                tasks[kept] = tasks[i];
                dues[kept] = dues[i];
                sequences[kept] = sequences[i];
                kept++;
            }
        }
        Arrays.fill(tasks, kept, size, null);
        size = kept;
        for (int i = (size - 2) / ARITY; i >= 0 && size > 1; i--) {
            siftDown(i, tasks[i], dues[i], sequences[i]);
        }
    }

    private void siftUp(int at, SimTask task, long due, long sequence) {
        while (at > 0) {
            int parent = (at - 1) / ARITY;
            long pd = dues[parent];
            if (due > pd || (due == pd && sequence > sequences[parent])) {
                break;
            }
            put(at, tasks[parent], pd, sequences[parent]);
            at = parent;
        }
        put(at, task, due, sequence);
    }

    private void siftDown(int at, SimTask task, long due, long sequence) {
        while (true) {
            int first = at * ARITY + 1;
            if (first >= size) {
                break;
            }
            int least = first;
            long ld = dues[first];
            long ls = sequences[first];
            int end = Math.min(first + ARITY, size);
            for (int c = first + 1; c < end; c++) {
                long cd = dues[c];
                if (cd < ld || (cd == ld && sequences[c] < ls)) {
                    least = c;
                    ld = cd;
                    ls = sequences[c];
                }
            }
            if (due < ld || (due == ld && sequence < ls)) {
                break;
            }
            put(at, tasks[least], ld, ls);
            at = least;
        }
        put(at, task, due, sequence);
    }

    private void put(int at, SimTask task, long due, long sequence) {
        tasks[at] = task;
        dues[at] = due;
        sequences[at] = sequence;
    }
}
