package net.smc.core.transport;

import java.util.ArrayDeque;
import java.util.Queue;
import java.util.concurrent.Executor;

/** An executor that only queues; the test runs the queue when it chooses. Thread-safe. */
public final class QueueExecutor implements Executor {
    private final Queue<Runnable> queue = new ArrayDeque<>();
    private final Signal signal;

    public QueueExecutor(Signal signal) {
        this.signal = signal;
    }

    @Override
    public void execute(Runnable task) {
        synchronized (this) {
            queue.add(task);
        }
        signal.changed();
    }

    public synchronized int size() {
        return queue.size();
    }

    /** Runs what is queued now (not what those tasks queue); returns how many ran. */
    public int runQueued() {
        int n;
        synchronized (this) {
            n = queue.size();
        }
        for (int i = 0; i < n; i++) {
            Runnable next;
            synchronized (this) {
                next = queue.poll();
            }
            next.run();
        }
        return n;
    }
}
