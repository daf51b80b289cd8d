package net.smc.core.message;

import java.math.BigDecimal;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

/**
 * PonderTalk values as messages carry them: a {@link String}, a {@link BigDecimal}, a
 * {@link Boolean}, {@code null} (nil), or a {@link List} of those, nested at most
 * {@link WireFormat#MAX_VALUE_DEPTH} deep. Checking and copying happen together so that a record
 * holds only values the codec can write, in lists nobody else can change. Lists allow nil
 * elements, so they are copied into unmodifiable {@code ArrayList}s rather than {@code List.copyOf}.
 */
final class ValueLimits {
    private ValueLimits() {
    }

    /** An immutable deep copy of a list of values. */
    static List<Object> list(String field, List<?> values) {
        if (values != null && fits(values, 0)) {
            return copy(values);
        }
        return list(field, values, 0); // throws, naming the field and element that broke a rule
    }

    /** A checked value (lists copied deeply). */
    static Object value(String field, Object value) {
        // A list given as a value is one level down already, as value(String, Object, int) counts.
        if (value instanceof List<?> l ? 1 <= WireFormat.MAX_VALUE_DEPTH && fits(l, 1) : fitsScalar(value)) {
            return value instanceof List<?> l ? copy(l) : value;
        }
        return value(field, value, 0);
    }

    // The checks without names: most messages (every subtree report, twice a second per cell) carry
    // values that fit, and naming each element for a message that is never shown cost a string each.
    // The named checks below run only when these fail, and throw.

    /** Whether {@code values} (at {@code depth}) and everything in it fit the rules. */
    private static boolean fits(List<?> values, int depth) {
        if (values.size() > WireFormat.MAX_VALUES) {
            return false;
        }
        for (int i = 0; i < values.size(); i++) {
            Object v = values.get(i);
            if (v instanceof List<?> l ? depth + 1 > WireFormat.MAX_VALUE_DEPTH || !fits(l, depth + 1) : !fitsScalar(v)) {
                return false;
            }
        }
        return true;
    }

    private static boolean fitsScalar(Object v) {
        if (v == null || v instanceof Boolean) {
            return true;
        }
        if (v instanceof String s) {
            int bytes = Utf8.length(s);
            return bytes >= 0 && bytes <= WireFormat.MAX_VALUE_STRING;
        }
        return v instanceof BigDecimal d && d.unscaledValue().bitLength() / 8 + 1 <= WireFormat.MAX_NUMBER_BYTES;
    }

    /** An unmodifiable deep copy of values that {@link #fits}. */
    private static List<Object> copy(List<?> values) {
        List<Object> copy = new ArrayList<>(values.size());
        for (int i = 0; i < values.size(); i++) {
            Object v = values.get(i);
            copy.add(v instanceof List<?> l ? copy(l) : v);
        }
        return Collections.unmodifiableList(copy);
    }

    private static List<Object> list(String field, List<?> values, int depth) {
        if (values == null) {
            throw new IllegalArgumentException(field + " is null; it must be a list of PonderTalk values");
        }
        if (values.size() > WireFormat.MAX_VALUES) {
            throw new IllegalArgumentException(field + " has " + values.size() + " elements; at most "
                    + WireFormat.MAX_VALUES + " are allowed");
        }
        List<Object> copy = new ArrayList<>(values.size());
        for (int i = 0; i < values.size(); i++) {
            Object v = values.get(i);
            copy.add(v instanceof List<?> ? value(field + "[" + i + "]", v, depth) : scalar(field, i, v));
        }
        return Collections.unmodifiableList(copy);
    }

    private static Object value(String field, Object v, int depth) {
        if (v instanceof List<?> l) {
            if (depth + 1 > WireFormat.MAX_VALUE_DEPTH) {
                throw new IllegalArgumentException(field + " is a list nested " + (depth + 1)
                        + " deep; PonderTalk values nest at most " + WireFormat.MAX_VALUE_DEPTH + " deep");
            }
            return list(field, l, depth + 1);
        }
        return scalar(field, -1, v);
    }

    private static Object scalar(String field, int index, Object v) {
        if (v == null || v instanceof Boolean) {
            return v;
        }
        String where = index < 0 ? field : field + "[" + index + "]";
        if (v instanceof String s) {
            return Fields.string(where, s, 0, WireFormat.MAX_VALUE_STRING, "a string value");
        }
        if (v instanceof BigDecimal d) {
            int bytes = d.unscaledValue().bitLength() / 8 + 1;
            if (bytes > WireFormat.MAX_NUMBER_BYTES) {
                throw new IllegalArgumentException(where + " " + d.toString().substring(0, 20) + "... needs " + bytes
                        + " bytes; a number must fit " + WireFormat.MAX_NUMBER_BYTES + " bytes (about 150 digits)");
            }
            return d;
        }
        throw new IllegalArgumentException(where + " is a " + v.getClass().getName() + " (" + v
                + "); a PonderTalk value must be a String, BigDecimal, Boolean, null or a List of those");
    }
}
