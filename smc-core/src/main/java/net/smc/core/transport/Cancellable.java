package net.smc.core.transport;

/** The handle of a task given to a {@link Scheduler}: lets its owner call it off. */
@FunctionalInterface
public interface Cancellable {

    /**
     * Calls the task off. When called on the cell's own thread, the task is guaranteed not to run
     * afterwards. Cancelling a task that already ran or was already cancelled does nothing.
     *
     * @return true when this call stopped the task from running, false when it had already run or
     *         had been cancelled before
     */
    boolean cancel();
}
