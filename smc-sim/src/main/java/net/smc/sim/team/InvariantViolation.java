package net.smc.sim.team;

import java.util.List;

/**
 * A team invariant broke: which, when, under which seed, and what the cells did just before. Run
 * the same scenario with the same seed to replay it exactly.
 */
public final class InvariantViolation extends RuntimeException {
    private final long seed;
    private final long timeMillis;
    private final List<String> trace;

    public InvariantViolation(String what, long seed, long timeMillis, List<String> trace) {
        super(what + " (seed " + seed + ", at " + timeMillis + " ms of simulated time; replay with this seed)");
        this.seed = seed;
        this.timeMillis = timeMillis;
        this.trace = List.copyOf(trace);
    }

    public long seed() {
        return seed;
    }

    public long timeMillis() {
        return timeMillis;
    }

    /** The last lines of the cells' trace before the violation, oldest first. */
    public List<String> trace() {
        return trace;
    }

    /** The message, then the trace, one event a line. */
    public String report() {
        return getMessage() + "\n" + String.join("\n", trace);
    }
}
