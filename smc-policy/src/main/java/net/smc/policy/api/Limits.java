package net.smc.policy.api;

/**
 * Bounds on what one run may do, so that no input can hang or crash a cell.
 *
 * @param maxSteps      message sends one run (a unit, or an event raised from Java) may make
 * @param maxCallDepth  block calls that may be nested (event loops and recursion end here)
 * @param maxUnitChars  characters of source one unit may have
 */
public record Limits(long maxSteps, int maxCallDepth, int maxUnitChars) {
    /** 100 million sends, 1,000 nested calls, 64 Mi characters. */
    public static final Limits DEFAULT = new Limits(100_000_000L, 1000, 64 * 1024 * 1024);

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
    }

    public Limits withMaxSteps(long steps) {
        return new Limits(steps, maxCallDepth, maxUnitChars);
    }

    public Limits withMaxCallDepth(int depth) {
        return new Limits(maxSteps, depth, maxUnitChars);
    }
}
