package net.smc.demo;

import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

/**
 * What ends a running {@code smc node} or {@code smc run}: the process being asked to end (SIGTERM,
 * SIGINT: a JVM shutdown hook), or, in tests, {@link #trigger}. The node waits in {@link #await()},
 * closes its cell, and then {@link #close()}s this signal; {@code smc run} has its cell stopped by
 * {@link #whenTriggered} and closes the signal once it has said so. A shutdown hook waits for the
 * close (at most {@value #CLOSE_WAIT_SECONDS} s), so the JVM does not halt while the command is
 * still ending; then it halts with its status for the signal (130 for SIGINT, 143 for SIGTERM).
 */
final class StopSignal implements AutoCloseable {
    static final long CLOSE_WAIT_SECONDS = 10;

    private final CountDownLatch stop = new CountDownLatch(1);
    private final CountDownLatch closed = new CountDownLatch(1);
    private volatile String reason = "";
    private Runnable onTrigger = () -> {
    };
    private Thread hook;

    /** A signal only {@link #trigger} fires: for nodes run in-process by tests. */
    static StopSignal manual() {
        return new StopSignal();
    }

    /** A signal the JVM's shutdown fires (SIGTERM, SIGINT, {@code System.exit}): for the {@code smc} process. */
    static StopSignal onShutdown() {
        StopSignal signal = new StopSignal();
        signal.hook = new Thread(signal::onShutdownHook, "smc-node-shutdown");
        Runtime.getRuntime().addShutdownHook(signal.hook);
        return signal;
    }

    /** Asks the command to stop; {@code why} ends up in its last line. Later calls do nothing. */
    void trigger(String why) {
        Runnable action;
        synchronized (this) {
            if (stop.getCount() == 0) {
                return;
            }
            reason = why;
            stop.countDown();
            action = onTrigger;
        }
        action.run();
    }

    /**
     * Runs {@code action} when the signal fires, on the thread that fires it (at once, if it has
     * fired already): {@code action} must only ask what runs to stop, not wait for it.
     */
    void whenTriggered(Runnable action) {
        synchronized (this) {
            if (stop.getCount() > 0) {
                onTrigger = action;
                return;
            }
        }
        action.run();
    }

    /** Whether the signal has fired. */
    boolean triggered() {
        return stop.getCount() == 0;
    }

    /** Why the signal fired ({@code ""} while it has not). */
    String reason() {
        return reason;
    }

    /**
     * Waits until the signal fires or {@code millis} have passed.
     *
     * @return whether it fired
     */
    boolean await(long millis) throws InterruptedException {
        return stop.await(millis, TimeUnit.MILLISECONDS);
    }

    /** Waits until the node is asked to stop, and answers why. */
    String await() throws InterruptedException {
        stop.await();
        return reason;
    }

    /** The node has closed: a waiting shutdown hook may let the JVM halt. */
    @Override
    public void close() {
        closed.countDown();
        if (hook != null && Thread.currentThread() != hook) {
            try {
                Runtime.getRuntime().removeShutdownHook(hook);
            } catch (IllegalStateException shuttingDown) {
                // the hook is running or has run; it returns once closed is counted down
            }
        }
    }

    private void onShutdownHook() {
        trigger("the process was asked to end (SIGTERM or SIGINT)");
        try {
            closed.await(CLOSE_WAIT_SECONDS, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
