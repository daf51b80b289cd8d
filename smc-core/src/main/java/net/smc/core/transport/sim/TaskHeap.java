package net.smc.core.transport.sim;

import java.util.Arrays;

/**
 * The {@link SimulationScheduler}'s queue: a 4-ary min-heap of {@link SimTask}s ordered by due time,
 * then by sequence number. The order is total (sequence numbers are unique), so the tasks come out
 * in exactly the order any correct priority queue would give; this one compares the two fields
 * directly and, four children to a node, has half the levels of a binary heap, which matters when
 * a large team keeps hundreds of thousands of datagrams in flight.
 */
final class TaskHeap {
    private static final int ARITY = 4;

    private SimTask[] tasks = new SimTask[256];
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
            tasks = Arrays.copyOf(tasks, size * 2);
        }
        siftUp(size++, task);
    }

    /** Removes and returns the first task, or null when empty. */
    SimTask poll() {
        if (size == 0) {
            return null;
        }
        SimTask first = tasks[0];
        SimTask last = tasks[--size];
        tasks[size] = null;
        if (size > 0) {
            siftDown(0, last);
        }
        return first;
    }

    /** Drops every cancelled task and restores the heap (linear time). */
    void removeCancelled() {
        int kept = 0;
        for (int i = 0; i < size; i++) {
            if (!tasks[i].isCancelled()) {
                tasks[kept++] = tasks[i];
            }
        }
        Arrays.fill(tasks, kept, size, null);
        size = kept;
        for (int i = (size - 2) / ARITY; i >= 0 && size > 1; i--) {
            siftDown(i, tasks[i]);
        }
    }

    private static boolean before(SimTask a, SimTask b) {
        return a.due < b.due || (a.due == b.due && a.sequence < b.sequence);
    }

    private void siftUp(int at, SimTask task) {
        while (at > 0) {
            int parent = (at - 1) / ARITY;
            SimTask p = tasks[parent];
            if (!before(task, p)) {
                break;
            }
            tasks[at] = p;
            at = parent;
        }
        tasks[at] = task;
    }

    private void siftDown(int at, SimTask task) {
        while (true) {
            int first = at * ARITY + 1;
            if (first >= size) {
                break;
            }
            int least = first;
            int end = Math.min(first + ARITY, size);
            for (int c = first + 1; c < end; c++) {
                if (before(tasks[c], tasks[least])) {
                    least = c;
                }
            }
            if (!before(tasks[least], task)) {
                break;
            }
            tasks[at] = tasks[least];
            at = least;
        }
        tasks[at] = task;
    }
}
