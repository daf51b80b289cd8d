package net.smc.core.transport;

/**
 * Runs a task on the cell's thread after a delay: the only way a cell waits. Protocol code uses it
 * for timeouts, retransmissions and heartbeats, and never sleeps.
 *
 * <p>Tasks run one at a time on the cell's thread, never inside {@link #schedule}: even a delay of
 * 0 runs the task later, after the caller returns. Tasks due at the same time run in the order
 * they were scheduled (guaranteed by the simulation; in deployment, by the timer's ordering).
 */
public interface Scheduler {

    /**
     * Schedules {@code task} to run once, {@code delayMillis} milliseconds from now.
     *
     * @param delayMillis the delay in milliseconds, 0 or more
     * @return a handle that cancels the task
     * @throws IllegalArgumentException when the delay is negative
     */
    Cancellable schedule(long delayMillis, Runnable task);

    /** Checks a delay given to {@link #schedule}; shared by the implementations. */
    static void checkDelay(long delayMillis) {
        if (delayMillis < 0) {
            throw new IllegalArgumentException("delay of " + delayMillis + " ms is negative; it must be 0 or more");
        }
    }
}
