package net.smc.core.security;

/**
 * Bytes that do not parse as what they claim to be. Thrown and caught inside this package only
 * (a datagram reader leaves early with it), so it is cheap: no stack trace.
 */
final class Malformed extends Exception {
    private static final long serialVersionUID = 1L;

    Malformed(String message) {
        super(message, null, false, false);
    }
}
