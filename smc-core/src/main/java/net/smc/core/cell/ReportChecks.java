package net.smc.core.cell;

import java.util.concurrent.atomic.AtomicLong;

/**
 * A check for tests of the report a cell keeps between ticks: a cell builds the report it sends its
 * parent again only when something it is built from moved (its seats, children, their reports, its
 * state, its lease), so a writer of those that does not say so would leave a stale report. With the
 * checks on, every cell also builds the report afresh at every tick where it would keep the old one,
 * and counts whether the two agree. Off by default (then the count stays put and costs nothing).
 * Global to the JVM: meant for a test that runs simulations one at a time.
 */
public final class ReportChecks {
    private static volatile boolean on;
    private static final AtomicLong AGREED = new AtomicLong();
    private static final AtomicLong STALE = new AtomicLong();

    private ReportChecks() {
    }

    /** Turns the checks on or off and clears the counts. */
    public static void enable(boolean enabled) {
        AGREED.set(0);
        STALE.set(0);
        on = enabled;
    }

    /** Kept reports found equal to a fresh build since the checks were turned on. */
    public static long agreed() {
        return AGREED.get();
    }

    /** Kept reports found to differ from a fresh build: each one a change some writer did not record. */
    public static long stale() {
        return STALE.get();
    }

    static boolean on() {
        return on;
    }

    static void compared(boolean equal) {
        (equal ? AGREED : STALE).incrementAndGet();
    }
}
