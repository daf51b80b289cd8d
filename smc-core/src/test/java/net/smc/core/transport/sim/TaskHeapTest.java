package net.smc.core.transport.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.PriorityQueue;
import java.util.Random;

import org.junit.jupiter.api.Test;

/** The scheduler's heap gives tasks in (due, sequence) order, as a reference priority queue does. */
class TaskHeapTest {
    private static final Comparator<SimTask> ORDER =
            Comparator.<SimTask>comparingLong(t -> t.due).thenComparingLong(t -> t.sequence);

    private final SimulationScheduler owner = new SimulationScheduler();
    private long sequence;

    private SimTask task(long due) {
        return new SimTask(owner, due, sequence++, () -> { });
    }

    @Test
    void empty_givesNothing() {
        TaskHeap heap = new TaskHeap();
        assertNull(heap.peek());
        assertNull(heap.poll());
        assertEquals(0, heap.size());
    }

    @Test
    void randomAddsAndPolls_comeOutAsFromAPriorityQueue() {
        Random random = new Random(42);
        for (int round = 0; round < 20; round++) {
            TaskHeap heap = new TaskHeap();
            PriorityQueue<SimTask> reference = new PriorityQueue<>(ORDER);
            for (int op = 0; op < 5_000; op++) {
                if (random.nextInt(3) > 0 || reference.isEmpty()) {
                    SimTask t = task(random.nextInt(50));   // many ties on the due time
                    heap.add(t);
                    reference.add(t);
                } else {
                    assertSame(reference.peek(), heap.peek());
                    assertSame(reference.poll(), heap.poll());
                }
                assertEquals(reference.size(), heap.size());
            }
            while (!reference.isEmpty()) {
                assertSame(reference.poll(), heap.poll());
            }
            assertNull(heap.poll());
        }
    }

    @Test
    void removeCancelled_keepsTheRestInOrder() {
        Random random = new Random(7);
        TaskHeap heap = new TaskHeap();
        List<SimTask> live = new ArrayList<>();
        for (int i = 0; i < 3_000; i++) {
            SimTask t = task(random.nextInt(100));
            heap.add(t);
            if (random.nextBoolean()) {
                t.cancel();
            } else {
                live.add(t);
            }
        }
        heap.removeCancelled();

        assertEquals(live.size(), heap.size());
        live.sort(ORDER);
        for (SimTask t : live) {
            assertSame(t, heap.poll());
        }
        assertNull(heap.poll());
    }
}
