package net.smc.core.transport.real;

import java.util.Objects;
import java.util.concurrent.Executor;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;

import net.smc.core.transport.Cancellable;
import net.smc.core.transport.Scheduler;

import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The scheduler of a deployed cell: a timer (a {@link ScheduledExecutorService}, which may be
 * shared by many cells) waits out the delay, then the task is handed to the cell's executor (a
 * {@link SerialExecutor}) and runs there, never on the timer's thread.
 *
 * <p>Cancelling from the cell's thread is final: the task checks on the cell's thread, just before
 * it runs, that it was not cancelled, so a task that was already on its way to the cell when it
 * was cancelled still does not run. The timer belongs to the caller, who shuts it down.
 */
public final class RealTimeScheduler implements Scheduler {
    private static final Logger log = LoggerFactory.getLogger(RealTimeScheduler.class);

    private final ScheduledExecutorService timer;
    private final Executor cellExecutor;

    public RealTimeScheduler(ScheduledExecutorService timer, Executor cellExecutor) {
        this.timer = Objects.requireNonNull(timer, "timer");
        this.cellExecutor = Objects.requireNonNull(cellExecutor, "cellExecutor");
    }

    @Override
    public Cancellable schedule(long delayMillis, Runnable task) {
        Objects.requireNonNull(task, "task");
        Scheduler.checkDelay(delayMillis);
        Timed timed = new Timed(task);
        timed.future = timer.schedule(timed::due, delayMillis, TimeUnit.MILLISECONDS);
        return timed;
    }

    private final class Timed implements Cancellable {
        private final Runnable task;
        private volatile boolean cancelled;
        private volatile boolean ran;
        private volatile ScheduledFuture<?> future;

        Timed(Runnable task) {
            this.task = task;
        }

        /** On the timer's thread: hand the task to the cell. */
        void due() {
            if (cancelled) {
                return;
            }
            try {
                cellExecutor.execute(this::runOnCell);
            } catch (RejectedExecutionException e) {
                log.debug("timer task dropped: the cell's executor is shut down", e);
            }
        }

        /** On the cell's thread. */
        private void runOnCell() {
            if (!cancelled) {
                ran = true;
                task.run();
            }
        }

        @Override
        public boolean cancel() {
            if (cancelled || ran) {
                return false;
            }
            cancelled = true;
            ScheduledFuture<?> f = future;
            if (f != null) {
                f.cancel(false);
            }
            return true;
        }
    }
}
