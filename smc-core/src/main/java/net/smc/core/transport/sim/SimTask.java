package net.smc.core.transport.sim;

import net.smc.core.transport.Cancellable;

/** A task waiting in the {@link SimulationScheduler}'s queue ({@link TaskHeap}), ordered by due time, then by sequence. */
final class SimTask implements Cancellable {
    private enum State { WAITING, RAN, CANCELLED }

    final long due;
    final long sequence;
    private final SimulationScheduler owner;
    private Runnable task;
    private State state = State.WAITING;

    SimTask(SimulationScheduler owner, long due, long sequence, Runnable task) {
        this.owner = owner;
        this.due = due;
        this.sequence = sequence;
        this.task = task;
    }

    boolean isCancelled() {
        return state == State.CANCELLED;
    }

    void run() {
        state = State.RAN;
        Runnable toRun = task;
        task = null;   // a handle kept by its creator does not keep the task's captures alive
        toRun.run();
    }

    @Override
    public boolean cancel() {
        if (state != State.WAITING) {
            return false;
        }
        state = State.CANCELLED;
        task = null;
        owner.cancelled();
        return true;
    }
}
