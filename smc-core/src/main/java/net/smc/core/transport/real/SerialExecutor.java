package net.smc.core.transport.real;

import java.util.ArrayDeque;
import java.util.Objects;
import java.util.Queue;
import java.util.concurrent.Executor;
import java.util.concurrent.RejectedExecutionException;

import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A cell's thread in a deployment: runs the tasks given to it one at a time, in the order given,
 * on a backing executor that may be a pool shared by many cells. Give the same serial executor to
 * a cell's {@link RealTimeScheduler} and its {@code UdpTransport}, and every input of the cell
 * (timer, datagram, command) is handled to completion before the next, as the sans-IO design needs.
 *
 * <p>A task that throws is logged and the next task runs: a fault in one input does not stop the
 * cell. To be fair to other cells on a shared pool, at most {@value #BATCH} tasks run in one turn
 * before the rest are handed back to the pool.
 */
public final class SerialExecutor implements Executor {
    private static final Logger log = LoggerFactory.getLogger(SerialExecutor.class);
    static final int BATCH = 64;

    private final Executor backing;
    private final Queue<Runnable> tasks = new ArrayDeque<>();   // guarded by this
    private boolean scheduled;                                   // guarded by this: a drain is queued or running

    public SerialExecutor(Executor backing) {
        this.backing = Objects.requireNonNull(backing, "backing");
    }

    /**
     * Queues {@code task} to run after every task queued before it.
     *
     * @throws RejectedExecutionException when the backing executor refuses (it was shut down)
     */
    @Override
    public void execute(Runnable task) {
        Objects.requireNonNull(task, "task");
        synchronized (this) {
            tasks.add(task);
            if (scheduled) {
                return;
            }
            scheduled = true;
        }
        submitDrain();
    }

    private void submitDrain() {
        try {
            backing.execute(this::drain);
        } catch (RejectedExecutionException e) {
            synchronized (this) {
                tasks.clear();
                scheduled = false;
            }
            throw e;
        }
    }

    private void drain() {
        for (int ran = 0; ran < BATCH; ran++) {
            Runnable next;
            synchronized (this) {
                next = tasks.poll();
                if (next == null) {
                    scheduled = false;
                    return;
                }
            }
            try {
                next.run();
            } catch (RuntimeException e) {
                log.error("a task of a cell's serial executor failed; the cell goes on with its next input", e);
            } catch (Error e) {
                synchronized (this) {
                    scheduled = false;   // the next execute starts a new turn
                }
                throw e;
            }
        }
        submitDrain();   // more are queued: yield the pool thread, keep the turn
    }
}
