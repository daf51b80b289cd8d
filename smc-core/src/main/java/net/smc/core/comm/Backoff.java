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
        double base = settings.baseTimeoutMillis(tries);
        double jitter = settings.jitterFraction();
        double spread = jitter == 0 ? 1.0 : 1.0 + jitter * (2 * random.nextDouble() - 1);
        long timeout = Math.round(base * spread);
        return Math.max(1, Math.min(timeout, settings.longestTimeoutMillis(tries)));
    }
}
