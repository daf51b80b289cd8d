package net.smc.core.comm;

import java.util.random.RandomGenerator;

/**
 * The timeout of each try: exponential growth up to a cap, spread by random jitter so that cells
 * which lost the same burst do not retransmit together. The random source is injected, so a
 * simulation replays the same timeouts for the same seed.
 */
final class Backoff {
    private final SenderSettings settings;
    private final RandomGenerator random;

    Backoff(SenderSettings settings, RandomGenerator random) {
        this.settings = settings;
        this.random = random;
    }

    /**
     * The wait for an Ack after transmission number {@code tries} (1 for the first): the base
     * timeout times a factor drawn from {@code [1 - jitter, 1 + jitter]}, rounded, 1 ms at least,
     * and never over {@link SenderSettings#longestTimeoutMillis(int)}.
     */
    long timeoutMillis(int tries) {
        return timeoutMillis(tries, settings.initialTimeoutMillis());
    }

    /**
     * The same when the first try's timeout is {@code firstMillis} (a round-trip estimate, never
     * above the initial timeout) instead of the initial timeout: each later try multiplies it by the
     * backoff factor, up to the cap, so no try waits longer than with the initial timeout.
     */
    long timeoutMillis(int tries, long firstMillis) {
        return jittered(tries, settings.baseTimeoutMillis(tries, firstMillis), spread());
    }

    /**
     * The wait for an Ack after try {@code tries} of a message whose copy leaves the transport
     * {@code queuedMillis} from now: the timeout backing off from {@code firstMillis} counted from
     * when the copy leaves, but never longer than the fixed schedule's from now (one jitter draw
     * spreads both). So a copy behind a short queue is not retransmitted while it waits, and no try
     * waits longer than with the fixed timeout, however deep the queue.
     */
    long timeoutMillis(int tries, long firstMillis, long queuedMillis) {
        double spread = spread();
        long fixed = jittered(tries, settings.baseTimeoutMillis(tries), spread);
        long measured = queuedMillis + jittered(tries, settings.baseTimeoutMillis(tries, firstMillis), spread);
        return Math.min(fixed, measured);
    }

    private long jittered(int tries, double base, double spread) {
        return Math.max(1, Math.min(Math.round(base * spread), settings.longestTimeoutMillis(tries)));
    }

    /**
     * When a message sent at {@code sentMillis} is given up on by an adaptive sender: the fixed
     * schedule's total ({@link SenderSettings#fixedScheduleMillis()}) spread by one jitter draw, so
     * within the failure bound.
     */
    long giveUpMillis(long sentMillis) {
        long total = Math.round(settings.fixedScheduleMillis() * spread());
        return sentMillis + Math.min(total, settings.failureBoundMillis());
    }

    /** A factor drawn from {@code [1 - jitter, 1 + jitter]}; 1 without jitter (and no draw). */
    private double spread() {
        double jitter = settings.jitterFraction();
        return jitter == 0 ? 1.0 : 1.0 + jitter * (2 * random.nextDouble() - 1);
    }
}
