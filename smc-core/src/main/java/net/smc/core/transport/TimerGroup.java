package net.smc.core.transport;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.Objects;
import java.util.Set;

/**
 * A {@link Scheduler} that remembers the tasks scheduled through it, so that one call cancels all
 * that have not run yet: what a cell does when it stops, and what a simulation does to a cell it
 * crashes (the cell's timers die with it while the rest of the team runs on).
 *
 * <p>Used from the cell's thread only, like the scheduler it wraps. Tasks that ran or were
 * cancelled are forgotten, so the group holds only pending tasks.
 */
public final class TimerGroup implements Scheduler {
    private final Scheduler scheduler;
    private final Set<Entry> pending = new LinkedHashSet<>();

    public TimerGroup(Scheduler scheduler) {
        this.scheduler = Objects.requireNonNull(scheduler, "scheduler");
    }

    @Override
    public Cancellable schedule(long delayMillis, Runnable task) {
        Objects.requireNonNull(task, "task");
        Entry entry = new Entry(task);
        entry.handle = scheduler.schedule(delayMillis, entry);
        pending.add(entry);
        return entry;
    }

    /** Cancels every task of this group that has not run yet; returns how many were cancelled. */
    public int cancelAll() {
        int cancelled = 0;
        for (Entry entry : new ArrayList<>(pending)) {
            if (entry.cancel()) {
                cancelled++;
            }
        }
        return cancelled;
    }

    /** How many tasks of this group have neither run nor been cancelled. */
    public int pending() {
        return pending.size();
    }

    private final class Entry implements Cancellable, Runnable {
        private final Runnable task;
        private Cancellable handle;

        Entry(Runnable task) {
            this.task = task;
        }

        @Override
        public void run() {
            pending.remove(this);
            task.run();
        }

        @Override
        public boolean cancel() {
            pending.remove(this);
            return handle.cancel();
        }
    }
}
