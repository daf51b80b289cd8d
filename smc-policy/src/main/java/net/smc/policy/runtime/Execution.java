package net.smc.policy.runtime;

import net.smc.policy.api.Limits;

/**
 * The state of one run: a unit, or an event raised from Java, with everything it triggers. It
 * counts sends against the step limit, what it builds against the built limit and its time against
 * the run time limit, tracks the depth of block calls and of policy firings, counts the errors it
 * reports (beyond {@link Limits#maxErrorsPerRun} they are suppressed, and counted), and knows the
 * current source (root, or the policy whose statements are running), which is the subject for
 * authorisation and where event delivery starts.
 */
public final class Execution {
    final CellRuntime runtime;
    private final long stepLimit;
    private final long startMillis;
    long stepsLeft;
    private long builtLeft;
    int depth;
    /** Obligation policies firing, nested: 1 inside the outermost one. */
    int firing;
    private int errorsReported;
    private long errorsSuppressed;
    Object source;

    Execution(CellRuntime runtime, Object source) {
        this.runtime = runtime;
        this.stepLimit = runtime.limits().maxSteps();
        this.stepsLeft = stepLimit;
        this.builtLeft = runtime.limits().maxBuiltPerRun();
        this.startMillis = runtime.limits().maxRunMillis() > 0 ? runtime.clock().getAsLong() : 0;
        this.source = source;
    }

    /** Refuses one more nested call at the call depth limit ({@link CallDepthExceeded}). */
    void checkCallDepth() {
        if (depth >= runtime.limits().maxCallDepth()) {
            throw new CallDepthExceeded(runtime.limits().maxCallDepth());
        }
    }

    /** Counts one nested call (a block call, a nested unit) against the call depth limit; {@link #leaveCall} ends it. */
    void enterCall() {
        checkCallDepth();
        depth++;
    }

    void leaveCall() {
        depth--;
    }

    /** Root, or the policy whose condition or action is running. */
    public Object source() {
        return source;
    }

    /**
     * Counts one send against the step limit, and every {@link Limits#CLOCK_CHECK_INTERVAL} sends
     * reads the clock and looks whether the cell was asked to stop.
     */
    void step() {
        long left = --stepsLeft;
        if (left < 0) {
            throw stepLimitExceeded();
        }
        if ((left & (Limits.CLOCK_CHECK_INTERVAL - 1)) == 0) {
            checkTime();
            checkStop();
        }
    }

    /**
     * Ends the run when the cell was asked to stop ({@link CellRuntime#stop}).
     *
     * @throws ExitRequest with the status the stop gave
     */
    void checkStop() {
        int status = runtime.stopStatus();
        if (status >= 0) {
            throw new ExitRequest(status);
        }
    }

    UnitAbort stepLimitExceeded() {
        stepsLeft = 0;
        return new UnitAbort("step limit of " + stepLimit + " sends exceeded");
    }

    /**
     * Counts {@code amount} characters or elements about to be built against the built limit.
     *
     * @throws UnitAbort when the run would build more than the limit allows
     */
    public void charge(long amount, String what) {
        if (amount > builtLeft) {
            builtLeft = 0;
            throw new UnitAbort("built limit of " + runtime.limits().maxBuiltPerRun()
                    + " characters and elements per run exceeded (by " + what + ")");
        }
        builtLeft -= amount;
    }

    private void checkTime() {
        long limit = runtime.limits().maxRunMillis();
        if (limit > 0) {
            long elapsed = runtime.clock().getAsLong() - startMillis;
            if (elapsed > limit) {
                throw new UnitAbort("time limit of " + limit + " ms per run exceeded (ran " + elapsed + " ms)");
            }
        }
    }

    /** Whether one more error of this run may be reported in full; counts it either way. */
    boolean admitError() {
        if (errorsReported < runtime.limits().maxErrorsPerRun()) {
            errorsReported++;
            return true;
        }
        errorsSuppressed++;
        return false;
    }

    /** Errors of this run that were not reported, beyond {@link Limits#maxErrorsPerRun}. */
    long errorsSuppressed() {
        return errorsSuppressed;
    }
}
