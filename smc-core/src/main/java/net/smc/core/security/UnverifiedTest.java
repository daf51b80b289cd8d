package net.smc.core.security;

/**
 * A receiver's test of a payload not yet authenticated: which payloads it would ignore whoever sent
 * them ({@link AuthenticatingTransport#setUnverifiedFilter}), which it reads before they are checked
 * ({@link AuthenticatingTransport#holdUnverified}). The payload is {@code data[offset, offset + length)},
 * read in place: the test must neither change nor keep the array, which is the transport's (so that
 * testing every payload that arrives copies none).
 */
@FunctionalInterface
public interface UnverifiedTest {
    /** The default of both: no payload passes. */
    UnverifiedTest NONE = (data, offset, length) -> false;

    /** Whether the payload {@code data[offset, offset + length)} passes. */
    boolean test(byte[] data, int offset, int length);
}
