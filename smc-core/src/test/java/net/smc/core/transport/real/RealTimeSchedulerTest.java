package net.smc.core.transport.real;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicReference;

import net.smc.core.transport.Cancellable;
import net.smc.core.transport.QueueExecutor;
import net.smc.core.transport.Signal;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

class RealTimeSchedulerTest {
    private static final long HANG_GUARD_MILLIS = 10_000;

    private final ScheduledExecutorService timer = Executors.newSingleThreadScheduledExecutor(r -> new Thread(r, "timer"));
    private final Signal signal = new Signal();
    private final QueueExecutor cell = new QueueExecutor(signal);
    private final RealTimeScheduler scheduler = new RealTimeScheduler(timer, cell);

    @AfterEach
    void stopTimer() {
        timer.shutdownNow();
    }

    @Test
    void dueTask_runsOnTheCellsExecutor_notOnTheTimer() throws Exception {
        ExecutorService cellThread = Executors.newSingleThreadExecutor(r -> new Thread(r, "cell"));
        try {
            AtomicReference<String> thread = new AtomicReference<>();
            CountDownLatch ran = new CountDownLatch(1);
            new RealTimeScheduler(timer, new SerialExecutor(cellThread)).schedule(1, () -> {
                thread.set(Thread.currentThread().getName());
                ran.countDown();
            });

            assertTrue(ran.await(HANG_GUARD_MILLIS, TimeUnit.MILLISECONDS), "hang guard");
            assertEquals("cell", thread.get());
        } finally {
            cellThread.shutdownNow();
        }
    }

    @Test
    void cancel_afterTheTimerFired_butBeforeTheCellRanIt_stillStopsIt() throws Exception {
        AtomicBoolean ran = new AtomicBoolean();
        Cancellable handle = scheduler.schedule(0, () -> ran.set(true));
        assertTrue(signal.await(() -> cell.size() == 1, HANG_GUARD_MILLIS), "hang guard");

        assertTrue(handle.cancel());
        cell.runQueued();

        assertFalse(ran.get());
    }

    @Test
    void cancel_beforeTheTaskIsDue_succeedsOnce() {
        Cancellable handle = scheduler.schedule(60_000, () -> { });
        assertTrue(handle.cancel());
        assertFalse(handle.cancel());
    }

    @Test
    void cancel_afterTheTaskRan_returnsFalse() throws Exception {
        AtomicBoolean ran = new AtomicBoolean();
        Cancellable handle = scheduler.schedule(0, () -> ran.set(true));
        assertTrue(signal.await(() -> cell.size() == 1, HANG_GUARD_MILLIS), "hang guard");
        cell.runQueued();

        assertTrue(ran.get());
        assertFalse(handle.cancel());
    }

    @Test
    void negativeDelay_isRefused() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> scheduler.schedule(-5, () -> { }));
        assertEquals("delay of -5 ms is negative; it must be 0 or more", e.getMessage());
    }
}
