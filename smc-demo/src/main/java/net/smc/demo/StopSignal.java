package net.smc.demo;

import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

/**
 * What ends a running {@code smc node}: the process being asked to end (SIGTERM, SIGINT: a JVM
 * shutdown hook), or, in tests, {@link #trigger}. The node waits in {@link #await()}, closes its cell,
 * and then {@link #close()}s this signal; a shutdown hook waits for that (at most
 * {@value #CLOSE_WAIT_SECONDS} s), so the JVM does not halt while the node is still closing.
 */
final class StopSignal implements AutoCloseable {
    static final long CLOSE_WAIT_SECONDS = 10;

    private final CountDownLatch stop = new CountDownLatch(1);
    private final CountDownLatch closed = new CountDownLatch(1);
    private volatile String reason = "";
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

    /** Asks the node to stop; {@code why} ends up in its last line. Later calls do nothing. */
    void trigger(String why) {
        if (stop.getCount() > 0) {
            reason = why;
            stop.countDown();
        }
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
