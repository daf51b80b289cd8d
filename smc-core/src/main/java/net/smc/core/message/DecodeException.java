package net.smc.core.message;

/**
 * Leaves the decoder early when a datagram is rejected. Cheap: no stack trace (a rejection is
 * ordinary input, not a bug), and it never escapes {@link MessageDecoder}.
 */
final class DecodeException extends Exception {
    private static final long serialVersionUID = 1L;

    private final RejectReason reason;

    DecodeException(RejectReason reason, String detail) {
        super(detail, null, false, false);
        this.reason = reason;
    }

    RejectReason reason() {
        return reason;
    }
}
