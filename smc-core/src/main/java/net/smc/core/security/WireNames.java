package net.smc.core.security;

import java.nio.ByteBuffer;
import java.nio.CharBuffer;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;

/**
 * The one rule for names on the wire (vehicle ids, missions): 1 to {@value #MAX_BYTES} bytes of
 * well-formed UTF-8, length-prefixed by one byte. Short, so that a credential stays a fraction of
 * a datagram; bounded, so that a reader never allocates what a sender claims.
 */
final class WireNames {
    /** The most UTF-8 bytes a vehicle id or a mission name may have. */
    static final int MAX_BYTES = 64;

    private WireNames() {
    }

    /**
     * The UTF-8 bytes of {@code value}.
     *
     * @param what  what the name is part of, for the error ("credential", "endpoint")
     * @param field which name it is ("vehicle id", "mission")
     * @throws IllegalArgumentException naming the field, the value and the rule
     */
    static byte[] encode(String value, String what, String field) {
        if (value == null) {
            throw new IllegalArgumentException(what + ": " + field + " is null");
        }
        ByteBuffer bytes;
        try {
            bytes = StandardCharsets.UTF_8.newEncoder()
                    .onMalformedInput(CodingErrorAction.REPORT)
                    .onUnmappableCharacter(CodingErrorAction.REPORT)
                    .encode(CharBuffer.wrap(value));
        } catch (CharacterCodingException e) {
            throw new IllegalArgumentException(what + ": " + field + " '" + value + "' is not well-formed Unicode");
        }
        int length = bytes.remaining();
        if (length == 0) {
            throw new IllegalArgumentException(what + ": " + field + " is empty; it must have 1 to " + MAX_BYTES + " bytes of UTF-8");
        }
        if (length > MAX_BYTES) {
            throw new IllegalArgumentException(what + ": " + field + " '" + value + "' is " + length
                    + " bytes of UTF-8; the limit is " + MAX_BYTES);
        }
        byte[] out = new byte[length];
        bytes.get(out);
        return out;
    }

    /** {@code value}, checked to be a valid name; the error calls it a peer id. */
    static String checkPeerId(String value) {
        encode(value, "endpoint", "peer id");
        return value;
    }

    /**
     * The name in {@code data[offset, offset + length)}, or null when it is not well-formed UTF-8.
     * ASCII (every id in practice) takes a fast path: this runs for every MAC'd datagram.
     */
    static String decode(byte[] data, int offset, int length) {
        int ascii = 0;
        while (ascii < length && data[offset + ascii] >= 0) {
            ascii++;
        }
        if (ascii == length) {
            return new String(data, offset, length, StandardCharsets.ISO_8859_1);
        }
        try {
            return StandardCharsets.UTF_8.newDecoder()
                    .onMalformedInput(CodingErrorAction.REPORT)
                    .onUnmappableCharacter(CodingErrorAction.REPORT)
                    .decode(ByteBuffer.wrap(data, offset, length)).toString();
        } catch (CharacterCodingException e) {
            return null;
        }
    }
}
