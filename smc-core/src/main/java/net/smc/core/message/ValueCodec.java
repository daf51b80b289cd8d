package net.smc.core.message;

import java.math.BigDecimal;
import java.math.BigInteger;
import java.util.ArrayList;
import java.util.List;

/**
 * PonderTalk values on the wire: a tag byte, then the value.
 * <pre>
 *   0 nil | 1 false | 2 true
 *   3 string: length 2, UTF-8 bytes (at most 4,096)
 *   4 number: scale 4 (signed), length 1 (1..64), unscaled value in minimal big-endian two's complement
 *   5 list:   count 1 (at most 64), then the elements (nested at most 4 deep)
 * </pre>
 * Every value has exactly one encoding (booleans are tags, numbers are minimal), so a decoded
 * value re-encodes to the bytes it came from, and {@code 1.0} stays distinct from {@code 1.00} as
 * it is for {@link BigDecimal#equals}.
 */
final class ValueCodec {
    static final int NIL = 0;
    static final int FALSE = 1;
    static final int TRUE = 2;
    static final int STRING = 3;
    static final int NUMBER = 4;
    static final int LIST = 5;

    private ValueCodec() {
    }

    static void writeList(List<?> values, WireWriter w) {
        w.u8(values.size());
        for (Object v : values) {
            write(v, w);
        }
    }

    static void write(Object v, WireWriter w) {
        if (v == null) {
            w.u8(NIL);
        } else if (v instanceof Boolean b) {
            w.u8(b ? TRUE : FALSE);
        } else if (v instanceof String s) {
            w.u8(STRING);
            w.string16(s);
        } else if (v instanceof BigDecimal d) {
            w.u8(NUMBER);
            w.i32(d.scale());
            byte[] unscaled = d.unscaledValue().toByteArray();
            w.u8(unscaled.length);
            w.bytes(unscaled);
        } else if (v instanceof List<?> l) {
            w.u8(LIST);
            writeList(l, w);
        } else {
            // Records admit only the types above (see ValueLimits).
            throw new IllegalStateException("not a PonderTalk value: " + v.getClass().getName());
        }
    }

    /** A list of values at depth 0 (a message's arguments or event values). */
    static List<Object> readList(WireReader r, String field) throws DecodeException {
        return readList(r, field, 0);
    }

    private static List<Object> readList(WireReader r, String field, int depth) throws DecodeException {
        int n = r.count(field, WireFormat.MAX_VALUES, 1);
        List<Object> list = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
            list.add(read(r, field, depth));
        }
        return list;
    }

    static Object read(WireReader r, String field) throws DecodeException {
        return read(r, field, 0);
    }

    private static Object read(WireReader r, String field, int depth) throws DecodeException {
        int tag = r.u8(field);
        switch (tag) {
            case NIL:
                return null;
            case FALSE:
                return Boolean.FALSE;
            case TRUE:
                return Boolean.TRUE;
            case STRING:
                return r.string16(field, WireFormat.MAX_VALUE_STRING);
            case NUMBER:
                return number(r, field);
            case LIST:
                if (depth + 1 > WireFormat.MAX_VALUE_DEPTH) {
                    throw new DecodeException(RejectReason.MALFORMED, field + " nests lists " + (depth + 1)
                            + " deep; at most " + WireFormat.MAX_VALUE_DEPTH + " are allowed");
                }
                return readList(r, field, depth + 1);
            default:
                throw new DecodeException(RejectReason.MALFORMED, field + " has value tag " + tag
                        + "; tags are 0 to 5");
        }
    }

    private static BigDecimal number(WireReader r, String field) throws DecodeException {
        int scale = r.i32(field);
        int len = r.u8(field);
        if (len == 0) {
            throw new DecodeException(RejectReason.MALFORMED, field + " is a number of 0 bytes; it needs 1 or more");
        }
        if (len > WireFormat.MAX_NUMBER_BYTES) {
            throw new DecodeException(RejectReason.OVERSIZED, field + " is a number of " + len + " bytes; at most "
                    + WireFormat.MAX_NUMBER_BYTES + " are allowed");
        }
        int at = r.take(len, field);
        byte[] b = r.array();
        if (len > 1 && (b[at] == 0 && b[at + 1] >= 0 || b[at] == -1 && b[at + 1] < 0)) {
            throw new DecodeException(RejectReason.MALFORMED, field + " is a number with a redundant sign byte;"
                    + " numbers are minimal two's complement");
        }
        return new BigDecimal(new BigInteger(b, at, len), scale);
    }
}
