package net.smc.core.capability;

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

    public CapabilityFormatException(String message, int offset) {
        super(message);
        this.offset = offset;
    }

    /** Where in the form the problem was found, in bytes from its first byte. */
    public int offset() {
        return offset;
    }
}
