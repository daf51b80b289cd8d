package net.smc.core.transport.sim;

/**
 * How one directed link of the {@link InMemoryNetwork} treats each datagram copy it carries.
 * Every duration is in milliseconds; every probability is from 0 to 1.
 *
 * <p>A copy that is not lost arrives after {@code latencyMillis} plus a uniform jitter from 0 to
 * {@code jitterMillis} (jitter alone re-orders datagrams sent close together); with probability
 * {@code reorderProbability} it is held back {@code reorderDelayMillis} more, so that later
 * datagrams overtake it; with probability {@code duplicateProbability} a second copy follows, with
 * its own delay.
 *
 * @param latencyMillis        the base one-way delay, 0 or more (0 still delivers later, never inside send)
 * @param jitterMillis         the largest extra delay, drawn uniformly, 0 or more
 * @param lossProbability      the chance that a copy is lost
 * @param duplicateProbability the chance that a delivered copy is delivered twice
 * @param reorderProbability   the chance that a copy is held back by {@code reorderDelayMillis}
 * @param reorderDelayMillis   how long a held-back copy waits, 1 or more when it can happen
 */
public record LinkProfile(long latencyMillis, long jitterMillis, double lossProbability,
                          double duplicateProbability, double reorderProbability, long reorderDelayMillis) {

    /** The default of a new network: 1 ms, no jitter, loss, duplication or re-ordering. */
    public static final LinkProfile DEFAULT = fixed(1);

    public LinkProfile {
        if (latencyMillis < 0) {
            throw new IllegalArgumentException("latency of " + latencyMillis + " ms is negative; it must be 0 or more");
        }
        if (jitterMillis < 0) {
            throw new IllegalArgumentException("jitter of " + jitterMillis + " ms is negative; it must be 0 or more");
        }
        checkProbability("loss", lossProbability);
        checkProbability("duplicate", duplicateProbability);
        checkProbability("reorder", reorderProbability);
        if (reorderDelayMillis < 0 || (reorderProbability > 0 && reorderDelayMillis == 0)) {
            throw new IllegalArgumentException("reorder delay of " + reorderDelayMillis
                    + " ms with reorder probability " + reorderProbability
                    + "; it must be 1 ms or more when re-ordering can happen, and never negative");
        }
    }

    /** A link with a fixed latency and no faults. */
    public static LinkProfile fixed(long latencyMillis) {
        return new LinkProfile(latencyMillis, 0, 0, 0, 0, 0);
    }

    public LinkProfile withLatency(long latencyMillis, long jitterMillis) {
        return new LinkProfile(latencyMillis, jitterMillis, lossProbability, duplicateProbability,
                reorderProbability, reorderDelayMillis);
    }

    public LinkProfile withLoss(double lossProbability) {
        return new LinkProfile(latencyMillis, jitterMillis, lossProbability, duplicateProbability,
                reorderProbability, reorderDelayMillis);
    }

    public LinkProfile withDuplication(double duplicateProbability) {
        return new LinkProfile(latencyMillis, jitterMillis, lossProbability, duplicateProbability,
                reorderProbability, reorderDelayMillis);
    }

    public LinkProfile withReorder(double reorderProbability, long reorderDelayMillis) {
        return new LinkProfile(latencyMillis, jitterMillis, lossProbability, duplicateProbability,
                reorderProbability, reorderDelayMillis);
    }

    private static void checkProbability(String name, double p) {
        if (!(p >= 0 && p <= 1)) {
            throw new IllegalArgumentException(name + " probability " + p + " is not a probability; it must be from 0 to 1");
        }
    }
}
