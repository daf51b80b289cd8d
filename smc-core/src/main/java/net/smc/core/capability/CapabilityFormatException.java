package net.smc.core.capability;

import net.smc.core.wire.WireProblem;

/**
 * Bytes that are not a well-formed capability summary or description: truncated, of another kind
 * or version, over a limit, not UTF-8, not canonical. The message names the form, the field (by
 * its record component path, e.g. {@code tasks[1].operations[0].name}), the byte offset and the
 * rule broken. Checked: the bytes come from another vehicle, and a bad reply must be handled (counted,
 * logged, dropped), never let through.
 */
public final class CapabilityFormatException extends Exception {
    private static final long serialVersionUID = 1L;

    private final int offset;
    private final WireProblem problem;

    public CapabilityFormatException(String message, int offset) {
        this(message, offset, WireProblem.MALFORMED);
    }

    public CapabilityFormatException(String message, int offset, WireProblem problem) {
        super(message);
        this.offset = offset;
        this.problem = problem;
    }

    /** What kind of problem it is: the form cut short, over a limit, or breaking a rule. */
    public WireProblem problem() {
        return problem;
    }

    /** Where in the form the problem was found, in bytes from its first byte. */
    public int offset() {
        return offset;
    }
}
