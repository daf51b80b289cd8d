package net.smc.policy.runtime;

/**
 * The state of one run: a unit, or an event raised from Java, with everything it triggers. It
 * counts sends against the step limit, tracks the depth of block calls, and knows the current
 * source (root, or the policy whose statements are running), which is the subject for
 * authorisation and where event delivery starts.
 */
public final class Execution {
    final CellRuntime runtime;
    private final long stepLimit;
    long stepsLeft;
    int depth;
    Object source;

    Execution(CellRuntime runtime, Object source) {
        this.runtime = runtime;
        this.stepLimit = runtime.limits().maxSteps();
        this.stepsLeft = stepLimit;
        this.source = source;
    }

    /** Root, or the policy whose condition or action is running. */
    public Object source() {
        return source;
    }

    UnitAbort stepLimitExceeded() {
        stepsLeft = 0;
        return new UnitAbort("step limit of " + stepLimit + " sends exceeded");
    }
}
