package net.smc.policy.api;

import net.smc.policy.lang.SourcePos;

/**
 * A PonderTalk runtime error. Thrown without a position by the operation that failed; the send
 * that invoked it fills in its own position, so the error names the failing send. Cheap: no stack
 * trace.
 */
public class PonderError extends RuntimeException {
    private SourcePos pos;

    public PonderError(String message) {
        super(message, null, false, false);
    }

    public PonderError(String message, SourcePos pos) {
        super(message, null, false, false);
        this.pos = pos;
    }

    /** Where the failing send is, or {@code null} if not yet known. */
    public SourcePos pos() {
        return pos;
    }

    /** Records the position of the failing send, unless an inner send already did. */
    public PonderError at(SourcePos where) {
        if (pos == null) {
            pos = where;
        }
        return this;
    }

    /** {@code source:line:col: message}, or the message alone without a position. */
    public String describe() {
        return pos == null ? getMessage() : pos + ": " + getMessage();
    }
}
