package net.smc.core.message;

import net.smc.core.wire.ByteReader;
import net.smc.core.wire.WireErrors;
import net.smc.core.wire.WireProblem;

/**
 * The datagram codec's fields on top of the shared {@link ByteReader}: names (cached in a
 * {@link StringCache}), strings, booleans and element counts, each checked against its limit and
 * against the bytes that remain before the caller allocates anything, so a datagram can never make
 * the decoder allocate more than the datagram itself could hold. Every error is a
 * {@link DecodeException} naming the field. Reused from datagram to datagram.
 */
final class DatagramReader extends ByteReader<DecodeException> {
    /** The codec's wording: "FIELD needs N bytes but M remain", with the reason the problem maps to. */
    private static final WireErrors<DecodeException> ERRORS = new WireErrors<>() {
        @Override
        public DecodeException error(WireProblem problem, int offset, String field, String rule) {
            return new DecodeException(reason(problem), field + " " + rule);
        }

        @Override
        public DecodeException truncated(int offset, String field, int needed, int left) {
            return new DecodeException(RejectReason.TRUNCATED, field + " needs " + needed + " bytes but " + left
                    + " remain");
        }

        @Override
        public DecodeException truncatedLength(int offset, String field, int needed, int left) {
            return truncated(offset, "the length of " + field, needed, left);
        }
    };

    private final StringCache names = new StringCache();

    DatagramReader() {
        super(ERRORS);
    }

    private static RejectReason reason(WireProblem problem) {
        return switch (problem) {
            case TRUNCATED -> RejectReason.TRUNCATED;
            case OVERSIZED -> RejectReason.OVERSIZED;
            case MALFORMED -> RejectReason.MALFORMED;
        };
    }

    boolean bool(String field) throws DecodeException {
        int b = u8(field);
        if (b > 1) {
            throw new DecodeException(RejectReason.MALFORMED, field + " is " + b + "; a boolean is 0 or 1");
        }
        return b == 1;
    }

    /** A name: one length byte, at most {@link WireFormat#MAX_NAME} bytes; cached. */
    String name(String field) throws DecodeException {
        return string8(field, WireFormat.MAX_NAME);
    }

    /** A string with a one-byte length, at most {@code max} bytes. */
    String string8(String field, int max) throws DecodeException {
        return string(field, length8(field), max);
    }

    /** A string with a one-byte length, at most {@code max} bytes, or null when its length is 0. */
    String senderOrNone(String field, int max) throws DecodeException {
        int len = length8(field);
        return len == 0 ? null : string(field, len, max);
    }

    /** A string with a two-byte length, at most {@code max} bytes. */
    String string16(String field, int max) throws DecodeException {
        return string(field, length16(field), max);
    }

    private String string(String field, int len, int max) throws DecodeException {
        if (len > max) {
            throw new DecodeException(RejectReason.OVERSIZED, field + " is " + len + " bytes; at most " + max
                    + " are allowed");
        }
        String s = names.get(array(), take(len, field), len);
        if (s == null) {
            throw new DecodeException(RejectReason.MALFORMED, field + " is not well-formed UTF-8");
        }
        return s;
    }

    /**
     * A one-byte element count, at most {@code max}, and no more than the remaining bytes could
     * hold at {@code minBytes} each: checked before the caller sizes a list by it.
     */
    int count(String field, int max, int minBytes) throws DecodeException {
        return checkCount(field, length8(field), max, minBytes);
    }

    /** A two-byte element count, checked as {@link #count} checks a one-byte one. */
    int count16(String field, int max, int minBytes) throws DecodeException {
        return checkCount(field, u16(field), max, minBytes);
    }

    private int checkCount(String field, int n, int max, int minBytes) throws DecodeException {
        if (n > max) {
            throw new DecodeException(RejectReason.OVERSIZED, field + " has " + n + " elements; at most " + max
                    + " are allowed");
        }
        if ((long) n * minBytes > remaining()) {
            throw new DecodeException(RejectReason.TRUNCATED, field + " has " + n + " elements but only "
                    + remaining() + " bytes remain");
        }
        return n;
    }

    /** Checks that every byte was read: a canonical payload has nothing after its last field. */
    void end() throws DecodeException {
        if (remaining() != 0) {
            throw new DecodeException(RejectReason.MALFORMED, remaining() + " bytes follow the last field");
        }
    }
}
