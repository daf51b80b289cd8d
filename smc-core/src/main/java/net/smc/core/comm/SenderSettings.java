package net.smc.core.comm;

/**
 * How the {@link MessageSender} retransmits and how long a receiver remembers what it delivered.
 * Every duration is in milliseconds.
 *
 * <p>A critical message is sent, then re-sent each time its timeout passes without an Ack. The
 * timeout of the first try is {@code initialTimeoutMillis}; each later try multiplies it by
 * {@code backoffFactor}, up to {@code maxTimeoutMillis}, so a congested or distant peer is not
 * flooded. Each timeout is then spread by a random factor in {@code [1 - jitterFraction,
 * 1 + jitterFraction]}, so cells that lost the same burst do not retransmit in lock-step. After
 * {@code maxTries} transmissions without an Ack the caller is told that delivery failed; that
 * happens at most {@link #failureBoundMillis()} after the send.
 *
 * <p><b>Adaptive first timeout.</b> When {@code minTimeoutMillis} is below {@code initialTimeoutMillis},
 * the first try's timeout to a peer is not fixed but estimated from measured round trips
 * ({@link RttEstimator}: the smoothed round trip plus four times its variation, as in RFC 6298),
 * clamped to {@code [minTimeoutMillis, initialTimeoutMillis]}: the peer's own estimate, else the
 * cell's over all its peers, else {@code initialTimeoutMillis} when nothing was measured. Later tries
 * grow from that by {@code backoffFactor} as above, and every timer runs from when the message has
 * left the cell's transport ({@code Transport.backlogMillis}). The time to give up stays that of the
 * fixed schedule: the last of the {@code maxTries} transmissions waits until the fixed schedule's
 * total time (the sum of its unjittered timeouts, spread by one jitter draw) has passed since the
 * send, so a peer is declared unreachable neither sooner nor later than with a fixed timeout, and
 * within {@link #failureBoundMillis()}. With {@code minTimeoutMillis} equal to
 * {@code initialTimeoutMillis} (the 7-argument constructor) the timeout is fixed, as before.
 *
 * <p>A receiver remembers the {@code (sender, id)} of each critical message it delivered for
 * {@code duplicateWindowMillis}, and at most {@code duplicateWindowEntries} of them, so that a
 * retransmission (whose Ack was lost) or a network duplicate is acknowledged again but delivered
 * only once. The window must outlast the retransmissions: it is checked to be at least
 * {@link #failureBoundMillis()}.
 *
 * @param initialTimeoutMillis   the wait for an Ack after the first transmission, 1 or more
 * @param backoffFactor          how much each timeout grows over the one before, 1.0 or more
 * @param maxTimeoutMillis       the longest wait for one try, at least the initial timeout
 * @param maxTries               transmissions before giving up, 1 to 1000 (1 means no retransmission)
 * @param jitterFraction         how far each timeout is spread at random, 0 (none) to 0.5
 * @param duplicateWindowMillis  how long a receiver remembers a delivered message, at least the failure bound
 * @param duplicateWindowEntries how many delivered messages a receiver remembers at most, 1 or more
 * @param minTimeoutMillis       the shortest first-try timeout the round-trip estimate may set, 1 to the
 *                               initial timeout; equal to it means a fixed first timeout
 */
public record SenderSettings(long initialTimeoutMillis, double backoffFactor, long maxTimeoutMillis, int maxTries,
                             double jitterFraction, long duplicateWindowMillis, int duplicateWindowEntries,
                             long minTimeoutMillis) {

    /**
     * 200 ms first timeout, doubling up to 2 s, 8 tries (given up after at most 13.2 s), 20 %
     * jitter; receivers remember 65,536 messages for 30 s.
     */
    public static final SenderSettings DEFAULTS = new SenderSettings(200, 2.0, 2_000, 8, 0.2, 30_000, 65_536);

    /** Settings with a fixed first timeout (no round-trip estimate): the minimum timeout is the initial one. */
    public SenderSettings(long initialTimeoutMillis, double backoffFactor, long maxTimeoutMillis, int maxTries,
                          double jitterFraction, long duplicateWindowMillis, int duplicateWindowEntries) {
        this(initialTimeoutMillis, backoffFactor, maxTimeoutMillis, maxTries, jitterFraction, duplicateWindowMillis,
                duplicateWindowEntries, initialTimeoutMillis);
    }

    public SenderSettings {
        if (initialTimeoutMillis < 1) {
            throw new IllegalArgumentException("initial timeout of " + initialTimeoutMillis
                    + " ms is too short; it must be 1 ms or more");
        }
        if (!(backoffFactor >= 1.0) || Double.isInfinite(backoffFactor)) {
            throw new IllegalArgumentException("backoff factor " + backoffFactor
                    + " would not grow the timeout; it must be a finite number 1.0 or more");
        }
        if (maxTimeoutMillis < initialTimeoutMillis) {
            throw new IllegalArgumentException("max timeout of " + maxTimeoutMillis
                    + " ms is below the initial timeout of " + initialTimeoutMillis + " ms; it must be at least that");
        }
        if (maxTries < 1 || maxTries > 1_000) {
            throw new IllegalArgumentException("max tries " + maxTries + " is out of range; it must be 1 to 1000");
        }
        if (!(jitterFraction >= 0 && jitterFraction <= 0.5)) {
            throw new IllegalArgumentException("jitter fraction " + jitterFraction
                    + " is out of range; it must be from 0 to 0.5");
        }
        if (duplicateWindowEntries < 1) {
            throw new IllegalArgumentException("duplicate window of " + duplicateWindowEntries
                    + " entries is too small; it must be 1 or more");
        }
        if (minTimeoutMillis < 1 || minTimeoutMillis > initialTimeoutMillis) {
            throw new IllegalArgumentException("min timeout of " + minTimeoutMillis
                    + " ms is out of range; it must be from 1 ms to the initial timeout of " + initialTimeoutMillis + " ms");
        }
        long bound = failureBound(initialTimeoutMillis, backoffFactor, maxTimeoutMillis, maxTries, jitterFraction);
        if (duplicateWindowMillis < bound) {
            throw new IllegalArgumentException("duplicate window of " + duplicateWindowMillis
                    + " ms is shorter than the " + bound + " ms over which a message may be retransmitted;"
                    + " it must be at least that, or a late retransmission would be delivered twice");
        }
    }

    /** The defaults with other retransmission times; the duplicate window grows to cover them if needed. */
    public SenderSettings withRetransmission(long initialTimeoutMillis, double backoffFactor, long maxTimeoutMillis,
                                             int maxTries) {
        long bound = failureBound(initialTimeoutMillis, backoffFactor, maxTimeoutMillis, maxTries, jitterFraction);
        return new SenderSettings(initialTimeoutMillis, backoffFactor, maxTimeoutMillis, maxTries, jitterFraction,
                Math.max(duplicateWindowMillis, bound), duplicateWindowEntries,
                adaptive() ? Math.min(minTimeoutMillis, initialTimeoutMillis) : initialTimeoutMillis);
    }

    public SenderSettings withJitter(double jitterFraction) {
        long bound = failureBound(initialTimeoutMillis, backoffFactor, maxTimeoutMillis, maxTries, jitterFraction);
        return new SenderSettings(initialTimeoutMillis, backoffFactor, maxTimeoutMillis, maxTries, jitterFraction,
                Math.max(duplicateWindowMillis, bound), duplicateWindowEntries, minTimeoutMillis);
    }

    public SenderSettings withDuplicateWindow(long duplicateWindowMillis, int duplicateWindowEntries) {
        return new SenderSettings(initialTimeoutMillis, backoffFactor, maxTimeoutMillis, maxTries, jitterFraction,
                duplicateWindowMillis, duplicateWindowEntries, minTimeoutMillis);
    }

    /**
     * These settings with a first timeout estimated per peer from measured round trips, never below
     * {@code minTimeoutMillis} nor above the initial timeout; {@code minTimeoutMillis} equal to the
     * initial timeout turns the estimate off.
     */
    public SenderSettings withAdaptiveTimeout(long minTimeoutMillis) {
        return new SenderSettings(initialTimeoutMillis, backoffFactor, maxTimeoutMillis, maxTries, jitterFraction,
                duplicateWindowMillis, duplicateWindowEntries, minTimeoutMillis);
    }

    /** Whether the first timeout is estimated from round trips (the minimum is below the initial timeout). */
    public boolean adaptive() {
        return minTimeoutMillis < initialTimeoutMillis;
    }

    /**
     * The fixed schedule's total wait, unjittered: the sum of every try's base timeout from the
     * initial timeout. A sender with an adaptive first timeout gives a message up this long after
     * its send, spread by one jitter draw, so that within {@link #failureBoundMillis()}.
     */
    public long fixedScheduleMillis() {
        double sum = 0;
        for (int t = 1; t <= maxTries; t++) {
            sum += baseTimeoutMillis(t);
        }
        return Math.round(sum);
    }

    /**
     * The longest time from sending a critical message to being told it failed, when no Ack ever
     * comes: the sum of every try's longest (jittered) timeout. A peer that is partitioned away or
     * crashed is reported failed within this bound (plus the scheduler's lateness in real time).
     */
    public long failureBoundMillis() {
        return failureBound(initialTimeoutMillis, backoffFactor, maxTimeoutMillis, maxTries, jitterFraction);
    }

    /** The unjittered timeout of try {@code tries} (1 for the first transmission). */
    double baseTimeoutMillis(int tries) {
        return base(initialTimeoutMillis, backoffFactor, maxTimeoutMillis, tries);
    }

    /** The unjittered timeout of try {@code tries} when the first try's timeout is {@code firstMillis}. */
    double baseTimeoutMillis(int tries, long firstMillis) {
        return base(firstMillis, backoffFactor, maxTimeoutMillis, tries);
    }

    /** The longest timeout try {@code tries} can draw. */
    long longestTimeoutMillis(int tries) {
        return (long) Math.ceil(baseTimeoutMillis(tries) * (1 + jitterFraction));
    }

    private static double base(long initial, double factor, long max, int tries) {
        return Math.min((double) max, initial * Math.pow(factor, tries - 1));
    }

    private static long failureBound(long initial, double factor, long max, int tries, double jitter) {
        long sum = 0;
        for (int t = 1; t <= tries; t++) {
            sum += (long) Math.ceil(base(initial, factor, max, t) * (1 + jitter));
        }
        return sum;
    }
}
