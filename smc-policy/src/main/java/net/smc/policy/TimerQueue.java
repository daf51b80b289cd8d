package net.smc.policy;

import net.smc.policy.api.TimerScheduler;
import java.util.Objects;
import java.util.OptionalLong;
import java.util.PriorityQueue;
import java.util.function.LongSupplier;

/**
 * The default {@link TimerScheduler}: a queue of tasks by due time on a given clock, run only when
 * its owner calls {@link #runDue()}. It never reads the wall clock or sleeps; the owner decides
 * when time has passed (the {@code smc} command waits for {@link #nextDue()}, a test advances a
 * virtual clock). Tasks due at the same time run in the order they were scheduled. Not thread-safe.
 */
public final class TimerQueue implements TimerScheduler {
    private final LongSupplier clock;
    private final PriorityQueue<Entry> queue = new PriorityQueue<>();
    private long sequence;
    private long ran;

    /** A queue on {@code clock}, in milliseconds since the epoch. */
    public TimerQueue(LongSupplier clock) {
        this.clock = Objects.requireNonNull(clock, "clock");
    }

    private static final class Entry implements Comparable<Entry> {
        final long due;
        final long order;
        final Runnable task;
        boolean cancelled;

        Entry(long due, long order, Runnable task) {
            this.due = due;
            this.order = order;
            this.task = task;
        }

        @Override
        public int compareTo(Entry o) {
            return due != o.due ? Long.compare(due, o.due) : Long.compare(order, o.order);
        }
    }

    @Override
    public Runnable schedule(long delayMillis, Runnable task) {
        if (delayMillis < 0) {
            throw new IllegalArgumentException("delay of " + delayMillis + " ms is negative; it must be 0 or more");
        }
        Entry e = new Entry(clock.getAsLong() + delayMillis, sequence++, Objects.requireNonNull(task, "task"));
        queue.add(e);
        return () -> {
            if (!e.cancelled) {
                e.cancelled = true;
                queue.remove(e);
            }
        };
    }

    /**
     * Runs every task due by the clock's present time, earliest first (also tasks that those tasks
     * schedule, if already due).
     *
     * @return how many tasks ran
     */
    public int runDue() {
        int count = 0;
        long now = clock.getAsLong();
        while (!queue.isEmpty() && queue.peek().due <= now) {
            Entry e = queue.poll();
            e.cancelled = true;
            count++;
            ran++;
            e.task.run();
        }
        return count;
    }

    /** When the earliest pending task is due, or empty when nothing is pending. */
    public OptionalLong nextDue() {
        return queue.isEmpty() ? OptionalLong.empty() : OptionalLong.of(queue.peek().due);
    }

    /** How many tasks wait. */
    public int pending() {
        return queue.size();
    }

    /** How many tasks have run since the queue was made. */
    public long ran() {
        return ran;
    }
}
