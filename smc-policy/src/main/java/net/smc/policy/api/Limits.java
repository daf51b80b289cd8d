package net.smc.policy.api;

/**
 * Bounds on what one run may do, so that no input can hang or crash a cell. A run is a unit, or an
 * event raised from Java, with everything it triggers (the policies it fires included).
 *
 * @param maxSteps        message sends (block calls included) one run may make
 * @param maxCallDepth    block calls that may be nested (event loops and recursion end here)
 * @param maxUnitChars    characters of source one unit may have
 * @param maxErrorsPerRun errors one run reports in full; later ones are counted, and one line at the
 *                        end of the run says how many were suppressed
 * @param maxBuiltPerRun  characters and elements one run may build: the length of every string a
 *                        concatenation or repetition makes, and the elements copied into arrays and
 *                        hashes by bulk operations (work that single sends hide from the step limit)
 * @param maxRunMillis    milliseconds one run may take by the cell's injected clock (checked every
 *                        {@value #CLOCK_CHECK_INTERVAL} sends); 0 for no time limit. A clock that
 *                        does not move during a run (a virtual one) never trips it.
 */
public record Limits(long maxSteps, int maxCallDepth, int maxUnitChars, int maxErrorsPerRun, long maxBuiltPerRun,
                     long maxRunMillis) {
    /** Sends between two readings of the clock for {@link #maxRunMillis}. */
    public static final int CLOCK_CHECK_INTERVAL = 1024;

    /**
     * 100 million sends, 1,000 nested calls, 64 Mi characters of source, 100 errors reported per run,
     * 256 Mi characters or elements built per run, 60 s per run.
     */
    public static final Limits DEFAULT = new Limits(100_000_000L, 1000, 64 * 1024 * 1024, 100,
            256L * 1024 * 1024, 60_000L);

    public Limits {
        if (maxSteps < 1) {
            throw new IllegalArgumentException("maxSteps is " + maxSteps + "; it must be 1 or more");
        }
        if (maxCallDepth < 1 || maxCallDepth > 100_000) {
            throw new IllegalArgumentException("maxCallDepth is " + maxCallDepth + "; it must be between 1 and 100000");
        }
        if (maxUnitChars < 1) {
            throw new IllegalArgumentException("maxUnitChars is " + maxUnitChars + "; it must be 1 or more");
        }
        if (maxErrorsPerRun < 1) {
            throw new IllegalArgumentException("maxErrorsPerRun is " + maxErrorsPerRun + "; it must be 1 or more");
        }
        if (maxBuiltPerRun < 1) {
            throw new IllegalArgumentException("maxBuiltPerRun is " + maxBuiltPerRun + "; it must be 1 or more");
        }
        if (maxRunMillis < 0) {
            throw new IllegalArgumentException("maxRunMillis is " + maxRunMillis + "; it must be 0 (none) or more");
        }
    }

    /** The first three bounds as given, the others as in {@link #DEFAULT}. */
    public Limits(long maxSteps, int maxCallDepth, int maxUnitChars) {
        this(maxSteps, maxCallDepth, maxUnitChars, DEFAULT.maxErrorsPerRun, DEFAULT.maxBuiltPerRun,
                DEFAULT.maxRunMillis);
    }

    public Limits withMaxSteps(long steps) {
        return new Limits(steps, maxCallDepth, maxUnitChars, maxErrorsPerRun, maxBuiltPerRun, maxRunMillis);
    }

    public Limits withMaxCallDepth(int depth) {
        return new Limits(maxSteps, depth, maxUnitChars, maxErrorsPerRun, maxBuiltPerRun, maxRunMillis);
    }

    public Limits withMaxErrorsPerRun(int errors) {
        return new Limits(maxSteps, maxCallDepth, maxUnitChars, errors, maxBuiltPerRun, maxRunMillis);
    }

    public Limits withMaxBuiltPerRun(long built) {
        return new Limits(maxSteps, maxCallDepth, maxUnitChars, maxErrorsPerRun, built, maxRunMillis);
    }

    public Limits withMaxRunMillis(long millis) {
        return new Limits(maxSteps, maxCallDepth, maxUnitChars, maxErrorsPerRun, maxBuiltPerRun, millis);
    }
}
