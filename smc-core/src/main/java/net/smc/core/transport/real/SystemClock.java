package net.smc.core.transport.real;

import net.smc.core.transport.Clock;

/**
 * The clock of a deployed cell: milliseconds since the epoch as read once at construction, then
 * advanced by {@link System#nanoTime()}. It never goes backwards and ignores steps of the host's
 * wall clock (NTP, a user), so a clock step cannot fire or suppress a timeout; the price is that
 * it drifts from the wall clock as the host's timer does.
 */
public final class SystemClock implements Clock {
    private final long startEpochMillis;
    private final long startNanos;

    public SystemClock() {
        this.startEpochMillis = System.currentTimeMillis();
        this.startNanos = System.nanoTime();
    }

    @Override
    public long nowMillis() {
        return startEpochMillis + (System.nanoTime() - startNanos) / 1_000_000;
    }
}
