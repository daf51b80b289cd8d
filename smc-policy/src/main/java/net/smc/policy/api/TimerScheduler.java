package net.smc.policy.api;

/**
 * Where a cell's timers wait: the engine never sleeps or starts a thread, it asks its scheduler to
 * run a task later on the cell's thread. A simulation gives its virtual-time scheduler (timers then
 * tick in virtual time and replay); a standalone cell uses a {@code net.smc.policy.TimerQueue} that its owner
 * drives. Given to {@code PolicyEngine.builder().scheduler(...)}.
 */
@FunctionalInterface
public interface TimerScheduler {

    /**
     * Runs {@code task} once, {@code delayMillis} milliseconds from now, on the cell's thread and
     * never inside this call. Tasks due at the same time run in the order they were scheduled.
     *
     * @param delayMillis 0 or more
     * @return an action that calls the task off (doing nothing once it ran or was called off)
     */
    Runnable schedule(long delayMillis, Runnable task);
}
