package net.smc.core.security;

import net.smc.core.wire.ByteReader;
import net.smc.core.wire.WireErrors;
import net.smc.core.wire.WireProblem;

/**
 * Bytes that do not parse as what they claim to be. Thrown and caught inside this package only
 * (a datagram reader leaves early with it), so it is cheap: no stack trace.
 */
final class Malformed extends Exception {
    private static final long serialVersionUID = 1L;

    Malformed(String message) {
        super(message, null, false, false);
    }

    /**
     * A reader of {@code data[start, end)} whose errors read "WHAT: FIELD at byte N: RULE", the
     * offset counted from {@code start}; {@code what} names the form ("credential", "signed datagram").
     */
    static ByteReader<Malformed> reader(byte[] data, int start, int end, String what) {
        return new ByteReader<>(new WireErrors<>() {
            @Override
            public Malformed error(WireProblem problem, int offset, String field, String rule) {
                return new Malformed(what + ": " + field + " at byte " + offset + ": " + rule);
            }

            @Override
            public Malformed truncatedLength(int offset, String field, int needed, int left) {
                return truncated(offset, field + " length", needed, left);
            }
        }, data, start, end);
    }
}
