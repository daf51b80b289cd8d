package net.smc.core.security;

import net.smc.core.transport.Transport;

/**
 * A payload that, once the envelope is added, would not fit one datagram. Refused rather than
 * split: the layer above knows how to split its own data (see {@link SecureEndpoint#maxPayload}).
 */
public final class PayloadTooLargeException extends IllegalArgumentException {
    private static final long serialVersionUID = 1L;

    private final int limit;

    PayloadTooLargeException(Protection protection, int payloadBytes, int overheadBytes, int limit) {
        super("payload of " + payloadBytes + " bytes does not fit a " + protection + " datagram: the envelope adds "
                + overheadBytes + " bytes and a datagram may carry at most "
                + Transport.MAX_DATAGRAM_BYTES + ", so the payload may be at most " + limit + " bytes");
        this.limit = limit;
    }

    /** The largest payload that would have fitted, in bytes. */
    public int limit() {
        return limit;
    }
}
