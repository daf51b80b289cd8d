package net.smc.policy.runtime;

/** {@code root exit} / {@code root exit: n}: unwinds everything that is running in the cell. */
public final class ExitRequest extends RuntimeException {
    private final int status;

    public ExitRequest(int status) {
        super(null, null, false, false);
        this.status = status;
    }

    public int status() {
        return status;
    }
}
