package net.smc.core.transport.sim;

import java.util.Objects;
import java.util.function.BooleanSupplier;

import net.smc.core.transport.Cancellable;
import net.smc.core.transport.Clock;
import net.smc.core.transport.Scheduler;

/**
 * Virtual time and the one scheduler that drives a whole simulation: every simulated cell, the
 * in-memory network and the world schedule on it, and time moves only when its owner runs it.
 * An hour of mission time costs only the work done in it, and the same inputs give the same run.
 *
 * <p>Tasks are kept in a priority queue ordered by (due time, sequence number): tasks due at the
 * same millisecond run in the order they were scheduled, whatever their origin. Nothing here reads
 * the wall clock or depends on hash order. Time jumps to each task's due time as it runs.
 *
 * <p>Single-threaded: use it, and everything it drives, from one thread. A task that throws stops
 * the run: the exception leaves {@link #step()} (or the {@code run} method that called it) with the
 * clock at the task's time and the task removed, so a simulation test fails where the fault is.
 */
public final class SimulationScheduler implements Clock, Scheduler {
    /** Below this many queued tasks, cancelled ones are left for the queue to drop as they come due. */
    private static final int PURGE_THRESHOLD = 1_024;

    private final TaskHeap queue = new TaskHeap();
    private long nowMillis;
    private long nextSequence;
    private int cancelledInQueue;
    private long executed;
    private boolean running;

    /** A scheduler whose clock starts at 0. */
    public SimulationScheduler() {
        this(0);
    }

    /** A scheduler whose clock starts at {@code startMillis} (e.g. an epoch time, for readable logs). */
    public SimulationScheduler(long startMillis) {
        this.nowMillis = startMillis;
    }

    @Override
    public long nowMillis() {
        return nowMillis;
    }

    @Override
    public Cancellable schedule(long delayMillis, Runnable task) {
        Objects.requireNonNull(task, "task");
        Scheduler.checkDelay(delayMillis);
        long due = nowMillis + delayMillis;
        if (due < nowMillis) {
            throw new IllegalArgumentException("delay of " + delayMillis + " ms from time " + nowMillis
                    + " overflows the clock; it must end before " + Long.MAX_VALUE);
        }
        SimTask simTask = new SimTask(this, due, nextSequence++, task);
        queue.add(simTask);
        return simTask;
    }

    /**
     * Runs the next task that is due (advancing the clock to its time), if there is one.
     *
     * @return true when a task ran, false when none was pending
     */
    public boolean step() {
        SimTask next = nextLive();
        if (next == null) {
            return false;
        }
        runTask(next);
        return true;
    }

    /**
     * Runs every task due at or before {@code timeMillis}, in order, including tasks they schedule
     * within that time, then sets the clock to {@code timeMillis}.
     *
     * @return how many tasks ran
     * @throws IllegalArgumentException when {@code timeMillis} is before now
     */
    public int runUntil(long timeMillis) {
        if (timeMillis < nowMillis) {
            throw new IllegalArgumentException("cannot run until " + timeMillis + " ms: the clock is already at "
                    + nowMillis + " ms and never goes back");
        }
        int ran = 0;
        for (SimTask next = nextLive(); next != null && next.due <= timeMillis; next = nextLive()) {
            runTask(next);
            ran++;
        }
        nowMillis = timeMillis;
        return ran;
    }

    /** Runs for {@code durationMillis} of virtual time ({@link #runUntil(long)} now + duration). */
    public int runFor(long durationMillis) {
        if (durationMillis < 0) {
            throw new IllegalArgumentException("duration of " + durationMillis + " ms is negative; it must be 0 or more");
        }
        return runUntil(nowMillis + durationMillis);
    }

    /**
     * Runs tasks until {@code condition} holds (checked before the first task and after each) or
     * the next task is due after {@code deadlineMillis}. The clock stays at the last task run.
     *
     * @return whether the condition holds
     */
    public boolean runUntil(BooleanSupplier condition, long deadlineMillis) {
        while (!condition.getAsBoolean()) {
            SimTask next = nextLive();
            if (next == null || next.due > deadlineMillis) {
                return false;
            }
            runTask(next);
        }
        return true;
    }

    /**
     * Runs tasks until none is pending.
     *
     * @param maxTasks a guard against a simulation that never goes idle (periodic timers do not)
     * @return how many tasks ran
     * @throws IllegalStateException when tasks are still pending after {@code maxTasks} have run
     */
    public int runUntilIdle(int maxTasks) {
        int ran = 0;
        while (step()) {
            ran++;
            if (ran >= maxTasks && pending() > 0) {
                throw new IllegalStateException("simulation not idle after " + ran + " tasks (limit " + maxTasks
                        + "); " + pending() + " still pending at " + nowMillis + " ms");
            }
        }
        return ran;
    }

    /** How many tasks are scheduled and neither ran nor were cancelled. */
    public int pending() {
        return queue.size() - cancelledInQueue;
    }

    /** How many tasks have run since this scheduler was made. */
    public long executed() {
        return executed;
    }

    /** Called by a task being cancelled while it waits in the queue. */
    void cancelled() {
        cancelledInQueue++;
        if (queue.size() > PURGE_THRESHOLD && cancelledInQueue > queue.size() / 2) {
            queue.removeCancelled();
            cancelledInQueue = 0;
        }
    }

    /** The next task not cancelled, still at the head of the queue; drops cancelled ones on the way. */
    private SimTask nextLive() {
        SimTask head = queue.peek();
        while (head != null && head.isCancelled()) {
            queue.poll();
            cancelledInQueue--;
            head = queue.peek();
        }
        return head;
    }

    private void runTask(SimTask task) {
        if (running) {
            throw new IllegalStateException("the simulation is already running a task; a task must not run the scheduler");
        }
        queue.poll();
        nowMillis = task.due;
        executed++;
        running = true;
        try {
            task.run();
        } finally {
            running = false;
        }
    }
}
