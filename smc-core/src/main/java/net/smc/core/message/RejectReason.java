package net.smc.core.message;

/**
 * Why the decoder discarded a datagram. The decoder counts every rejection by reason (see
 * {@link MessageDecoder#rejected(RejectReason)}), so that nothing is dropped silently.
 */
public enum RejectReason {
    /** The datagram ends before a field does: the header, the payload, or a length that points past the end. */
    TRUNCATED,
    /** The datagram is over {@link WireFormat#MAX_DATAGRAM} bytes, or a length or count is over its field's limit. */
    OVERSIZED,
    /** The first two bytes are not {@link WireFormat#MAGIC}: not one of ours. */
    BAD_MAGIC,
    /** A format version this build does not read. */
    UNKNOWN_VERSION,
    /** A type code (of the datagram or of a fragment's message) that no {@link MessageType} has. */
    UNKNOWN_TYPE,
    /**
     * The bytes break the encoding: bad UTF-8, an unassigned value tag, a boolean other than 0 or
     * 1, a non-minimal number, an unsorted set, bytes after the last field, a sender left to a
     * transport that names none.
     */
    MALFORMED,
    /** The fields decode but break a rule of their message (a negative level, an empty name): the record refused them. */
    INVALID_FIELD,
    /** A fragment frame whose index, count, total or chunk length is inconsistent, alone or with its siblings. */
    BAD_FRAGMENT,
    /** A fragment already held by a reassembly in progress (UDP duplicates packets). */
    DUPLICATE_FRAGMENT,
    /**
     * The decoder itself failed: a bug, caught so that a bad datagram never takes a cell down.
     * Counted and logged at warning level; tests and fuzzing assert it never happens.
     */
    INTERNAL_ERROR
}
