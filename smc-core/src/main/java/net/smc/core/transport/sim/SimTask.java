package net.smc.core.transport.sim;

import net.smc.core.transport.Cancellable;

/** A task waiting in the {@link SimulationScheduler}'s queue, ordered by due time, then by sequence. */
final class SimTask implements Cancellable, Comparable<SimTask> {
    private enum State { WAITING, RAN, CANCELLED }

    final long due;
    private final long sequence;
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

    @Override
    public int compareTo(SimTask other) {
        int byTime = Long.compare(due, other.due);
        return byTime != 0 ? byTime : Long.compare(sequence, other.sequence);
    }
}
