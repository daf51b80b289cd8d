package net.smc.core.transport.real;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;

import net.smc.core.transport.QueueExecutor;
import net.smc.core.transport.Signal;

import org.junit.jupiter.api.Test;

class SerialExecutorTest {
    private final QueueExecutor pool = new QueueExecutor(new Signal());
    private final List<Integer> ran = new ArrayList<>();

    @Test
    void tasks_runInOrder_inOneTurnOfThePool() {
        SerialExecutor cell = new SerialExecutor(pool);
        for (int i = 0; i < 3; i++) {
            int n = i;
            cell.execute(() -> ran.add(n));
        }

        assertEquals(1, pool.size(), "one turn is queued for all three");
        pool.runQueued();

        assertEquals(List.of(0, 1, 2), ran);
        assertEquals(0, pool.size());
    }

    @Test
    void aLongQueue_givesThePoolBackAfterABatch() {
        SerialExecutor cell = new SerialExecutor(pool);
        for (int i = 0; i < 100; i++) {
            int n = i;
            cell.execute(() -> ran.add(n));
        }

        pool.runQueued();
        assertEquals(SerialExecutor.BATCH, ran.size());
        assertEquals(1, pool.size(), "the rest wait for another turn");
        pool.runQueued();
        assertEquals(100, ran.size());
    }

    @Test
    void aTaskThatThrows_doesNotStopTheNext() {
        SerialExecutor cell = new SerialExecutor(pool);
        cell.execute(() -> {
            throw new IllegalStateException("a bad datagram");
        });
        cell.execute(() -> ran.add(1));

        pool.runQueued();

        assertEquals(List.of(1), ran);
    }

    @Test
    void aRefusingPool_refusesTheTask_andTheExecutorRecovers() {
        boolean[] refuse = {true};
        QueueExecutor later = new QueueExecutor(new Signal());
        SerialExecutor cell = new SerialExecutor(task -> {
            if (refuse[0]) {
                throw new RejectedExecutionException("shut down");
            }
            later.execute(task);
        });

        assertThrows(RejectedExecutionException.class, () -> cell.execute(() -> ran.add(0)));
        refuse[0] = false;
        cell.execute(() -> ran.add(1));
        later.runQueued();

        assertEquals(List.of(1), ran);
    }

    /** Four threads feed one serial executor on a four-thread pool: never two tasks at once, each feeder's order kept. */
    @Test
    void onAThreadPool_tasksNeverOverlap_andKeepTheirOrder() throws Exception {
        ExecutorService threads = Executors.newFixedThreadPool(4);
        ExecutorService feeders = Executors.newFixedThreadPool(4);
        try {
            SerialExecutor cell = new SerialExecutor(threads);
            AtomicInteger inside = new AtomicInteger();
            AtomicInteger overlaps = new AtomicInteger();
            List<List<Integer>> seen = new ArrayList<>();
            for (int f = 0; f < 4; f++) {
                seen.add(Collections.synchronizedList(new ArrayList<>()));
            }
            CountDownLatch done = new CountDownLatch(4 * 1_000);
            for (int f = 0; f < 4; f++) {
                int feeder = f;
                feeders.execute(() -> {
                    for (int i = 0; i < 1_000; i++) {
                        int n = i;
                        cell.execute(() -> {
                            if (inside.incrementAndGet() != 1) {
                                overlaps.incrementAndGet();
                            }
                            seen.get(feeder).add(n);
                            inside.decrementAndGet();
                            done.countDown();
                        });
                    }
                });
            }

            assertTrue(done.await(10, TimeUnit.SECONDS), "hang guard");
            assertEquals(0, overlaps.get());
            for (List<Integer> order : seen) {
                assertEquals(order.stream().sorted().toList(), order);
            }
        } finally {
            threads.shutdownNow();
            feeders.shutdownNow();
        }
    }
}
