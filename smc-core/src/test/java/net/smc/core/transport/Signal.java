package net.smc.core.transport;

import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;

/** Wakes a test thread waiting for real datagrams whenever a receiver records one. */
public final class Signal {

    /** Called by receivers after they record something. */
    public synchronized void changed() {
        notifyAll();
    }

    /**
     * Waits until {@code done} holds or {@code timeoutMillis} pass; a hang guard, not a speed check.
     *
     * @return whether {@code done} holds
     */
    public synchronized boolean await(BooleanSupplier done, long timeoutMillis) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(timeoutMillis);
        while (!done.getAsBoolean()) {
            long remaining = TimeUnit.NANOSECONDS.toMillis(deadline - System.nanoTime());
            if (remaining <= 0) {
                return false;
            }
            wait(remaining);
        }
        return true;
    }
}
