package net.smc.core.message;

/**
 * The kind of a {@link Message}, with the one-byte code that names it on the wire.
 *
 * <p>Codes are part of the wire format: a code, once given, is never changed and never given to
 * another type, even after its type is retired, so that a cell running an older build rejects a
 * newer message as {@link RejectReason#UNKNOWN_TYPE} instead of misreading it. New types take the
 * next free code. Two codes are reserved and never assigned: {@code 0x00} (so that a zeroed buffer
 * is never a message) and {@code 0xFF}, the codec's fragment frame, which carries a piece of a
 * message too large for one datagram and never reaches a handler.
 *
 * <table>
 * <caption>Assigned codes</caption>
 * <tr><th>code</th><th>type</th><th>code</th><th>type</th></tr>
 * <tr><td>0x01</td><td>DISCOVERY</td><td>0x09</td><td>HEARTBEAT</td></tr>
 * <tr><td>0x02</td><td>DISCOVERY_REPLY</td><td>0x0A</td><td>ACK</td></tr>
 * <tr><td>0x03</td><td>CAPABILITY_REQUEST</td><td>0x0B</td><td>ROLE_EVENT</td></tr>
 * <tr><td>0x04</td><td>CAPABILITY_REPLY</td><td>0x0C</td><td>INVOCATION</td></tr>
 * <tr><td>0x05</td><td>ROLE_ASSIGNMENT</td><td>0x0D</td><td>INVOCATION_RESULT</td></tr>
 * <tr><td>0x06</td><td>ASSIGNMENT_RESPONSE</td><td>0x0E</td><td>LEAVE</td></tr>
 * <tr><td>0x07</td><td>POLICY_REQUEST</td><td>0x0F</td><td>STATUS</td></tr>
 * <tr><td>0x08</td><td>POLICY_REPLY</td><td>0x10</td><td>ACKS</td></tr>
 * <tr><td>0x11</td><td>ROSTER</td><td>0x12</td><td>SUBTREE_REPORT</td></tr>
 * <tr><td>0x13</td><td>CELL_REQUEST</td><td>0x14</td><td>ECHO</td></tr>
 * <tr><td>0x15</td><td>WITHDRAWAL</td><td></td><td></td></tr>
 * <tr><td></td><td></td><td>0xFF</td><td>(fragment frame, reserved)</td></tr>
 * </table>
 */
public enum MessageType {
    DISCOVERY(0x01),
    DISCOVERY_REPLY(0x02),
    CAPABILITY_REQUEST(0x03),
    CAPABILITY_REPLY(0x04),
    ROLE_ASSIGNMENT(0x05),
    ASSIGNMENT_RESPONSE(0x06),
    POLICY_REQUEST(0x07),
    POLICY_REPLY(0x08),
    HEARTBEAT(0x09),
    ACK(0x0A),
    ROLE_EVENT(0x0B),
    INVOCATION(0x0C),
    INVOCATION_RESULT(0x0D),
    LEAVE(0x0E),
    STATUS(0x0F),
    ACKS(0x10),
    ROSTER(0x11),
    SUBTREE_REPORT(0x12),
    CELL_REQUEST(0x13),
    ECHO(0x14),
    WITHDRAWAL(0x15);

    private static final MessageType[] BY_CODE = new MessageType[256];

    static {
        for (MessageType t : values()) {
            if (t.code == WireFormat.FRAGMENT_CODE || t.code == 0 || BY_CODE[t.code] != null) {
                throw new ExceptionInInitializerError("message type code 0x"
                        + Integer.toHexString(t.code) + " of " + t + " is reserved or taken");
            }
            BY_CODE[t.code] = t;
        }
    }

    private final int code;

    MessageType(int code) {
        this.code = code;
    }

    /** The wire code, 0x01 to 0xFE. */
    public int code() {
        return code;
    }

    /**
     * The type with this wire code.
     *
     * @throws IllegalArgumentException if no type has it
     */
    public static MessageType fromCode(int code) {
        MessageType t = byCode(code);
        if (t == null) {
            throw new IllegalArgumentException("message type code " + code + " is not assigned; assigned codes are 1 to "
                    + values().length);
        }
        return t;
    }

    /** The type with this wire code, or null: the decoder's allocation-free lookup. */
    static MessageType byCode(int code) {
        return code >= 0 && code < 256 ? BY_CODE[code] : null;
    }
}
