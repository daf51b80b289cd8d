package net.smc.core.message;

/**
 * The constants of the wire format: the header, the datagram size and the limit of every field.
 * Message records enforce these limits in their constructors and the decoder enforces them on every
 * datagram, so both sides agree on what is valid. The layout is described in
 * <a href="doc-files/wire-format.md">the wire-format note</a>.
 *
 * <p>Sizes are in bytes; strings are counted in UTF-8 bytes, not characters.
 */
public final class WireFormat {
    /** The first two bytes of every datagram, "SM". */
    public static final int MAGIC = 0x534D;
    /** The only format version this build reads and writes (version 1 had a payload length and always named the sender). */
    public static final int VERSION = 2;
    /**
     * The type code of a fragment frame (one piece of a message too large for one datagram).
     * Never assigned to a {@link MessageType}.
     */
    public static final int FRAGMENT_CODE = 0xFF;

    /** The largest datagram written or accepted: below a typical 1,500-byte MTU with IP/UDP headers. */
    public static final int MAX_DATAGRAM = 1_400;
    /** Header bytes other than the sender: magic 2, version 1, type 1, sender length 1, id 8; the payload is the rest. */
    public static final int FIXED_HEADER = 13;
    /** Bytes of a fragment frame's own header: original type 1, index 2, count 2, total length 4. */
    public static final int FRAGMENT_HEADER = 9;
    /** The largest payload of one message, reassembled from fragments when it exceeds one datagram. */
    public static final int MAX_PAYLOAD = 65_535;
    /** The most fragments one message may be split into (a full payload needs at most 51). */
    public static final int MAX_FRAGMENTS = 64;

    /** A sender (vehicle id): 1 to 64 bytes. */
    public static final int MAX_SENDER = 64;
    /** A name (mission, role, vehicle, task, operation, event, resource, type name): 1 to 64 bytes. */
    public static final int MAX_NAME = 64;
    /** A policy URI: 1 to 255 bytes. */
    public static final int MAX_URI = 255;
    /** A short human-readable text (a reason, an error): 0 to 255 bytes. */
    public static final int MAX_TEXT = 255;
    /** The text of a policy file: 0 to 65,000 bytes (fragmented when longer than one datagram). */
    public static final int MAX_POLICY_TEXT = 65_000;
    /** The coding byte of a policy text sent as its UTF-8 bytes. */
    public static final int POLICY_TEXT_PLAIN = 0;
    /** The coding byte of a policy text sent as a zlib stream (RFC 1950: DEFLATE with an Adler-32 checksum, no preset dictionary). */
    public static final int POLICY_TEXT_DEFLATE = 1;
    /**
     * The coding byte of a policy text sent as a zlib stream deflated over the preset dictionary of
     * PonderTalk phrases (the stream names it by its Adler-32): what the encoder writes.
     */
    public static final int POLICY_TEXT_DEFLATE_DICTIONARY = 2;
    /**
     * The shortest policy text the encoder deflates (UTF-8 bytes); it sends the deflated form when
     * it is shorter than the text, else the text.
     */
    public static final int MIN_DEFLATED_POLICY_TEXT = 64;
    /** A PonderTalk string value: 0 to 4,096 bytes. */
    public static final int MAX_VALUE_STRING = 4_096;
    /** A PonderTalk number: its unscaled value in at most 64 bytes of two's complement. */
    public static final int MAX_NUMBER_BYTES = 64;
    /** Elements of one list of PonderTalk values (arguments, event values, a nested list). */
    public static final int MAX_VALUES = 64;
    /** Nesting of lists inside PonderTalk values: a list inside a value list is depth 1. */
    public static final int MAX_VALUE_DEPTH = 4;
    /** Policies named by one role assignment. */
    public static final int MAX_POLICIES = 32;
    /** Resources of one capability description or summary. */
    public static final int MAX_RESOURCES = 64;
    /** Tasks of one capability description or summary. */
    public static final int MAX_TASKS = 64;
    /** Operations, and separately events, of one task description. */
    public static final int MAX_OPERATIONS = 64;
    /** Argument types of one operation, and attributes of one event. */
    public static final int MAX_ARGUMENTS = 16;
    /**
     * Ids confirmed by one {@link Acks}: 1 + 128 x 8 bytes of payload, so that with the longest
     * sender it still fits one datagram.
     */
    public static final int MAX_ACKS = 128;

    private WireFormat() {
    }
}
