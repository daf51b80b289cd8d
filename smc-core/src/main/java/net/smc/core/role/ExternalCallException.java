package net.smc.core.role;

/** An invocation through a role's external interface did not happen, or failed; {@link #kind()} says which. */
public final class ExternalCallException extends RuntimeException {

    /** Why the call did not succeed. */
    public enum Kind {
        /** The role is not loaded on this cell. */
        NO_SUCH_ROLE,
        /** The operation or event is not in the role's external interface. */
        NOT_IN_INTERFACE,
        /** The role's authorisation policies (or the default decision) denied it. */
        DENIED,
        /** It was allowed, but the operation failed. */
        FAILED
    }

    private final Kind kind;

    public ExternalCallException(Kind kind, String message) {
        super(message);
        this.kind = kind;
    }

    public Kind kind() {
        return kind;
    }
}
