package net.smc.core.security;

/**
 * A receiver's test of a payload not yet authenticated ({@link AuthenticatingTransport#setUnverifiedFilter}):
 * whether the receiver would do nothing with it, whoever sent it. The payload is
 * {@code data[offset, offset + length)}, read in place: the test must neither change nor keep the
 * array, which is the transport's (so that testing every payload copies none).
 */
@FunctionalInterface
public interface UnverifiedFilter {
    /** The default: every payload is checked. */
    UnverifiedFilter NONE = (data, offset, length) -> false;

    /** Whether the receiver would ignore the payload {@code data[offset, offset + length)}. */
    boolean ignores(byte[] data, int offset, int length);
}
