package net.smc.core.wire;

/**
 * How one wire format reports bytes it cannot read: turns a problem, its byte offset, the field and
 * the rule broken into that format's own exception, worded that format's way. A {@link ByteReader}
 * calls it only when it throws, so building the message costs nothing on the path that succeeds.
 *
 * @param <E> the format's exception
 */
@FunctionalInterface
public interface WireErrors<E extends Exception> {
    /**
     * @param offset where the field starts, in bytes from where reading began
     * @param field  the field, as the format names it
     * @param rule   what is wrong, e.g. {@code "truncated: needs 8 bytes, 3 left"}
     */
    E error(WireProblem problem, int offset, String field, String rule);

    /** {@code field} needs {@code needed} bytes but only {@code left} remain. */
    default E truncated(int offset, String field, int needed, int left) {
        return error(WireProblem.TRUNCATED, offset, field, "truncated: needs " + needed + " bytes, " + left + " left");
    }

    /** The length (or count) in front of {@code field} needs {@code needed} bytes but only {@code left} remain. */
    default E truncatedLength(int offset, String field, int needed, int left) {
        return truncated(offset, field, needed, left);
    }
}
