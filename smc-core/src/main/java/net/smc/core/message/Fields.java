package net.smc.core.message;

import java.util.List;

/**
 * The field rules every message record applies in its constructor. Each failure names the field
 * (as {@code Record.field}), its value and the rule, e.g. {@code Heartbeat.role '' is 0 UTF-8
 * bytes; a name must be 1 to 64 bytes}.
 */
final class Fields {
    private Fields() {
    }

    /** A name: 1 to {@link WireFormat#MAX_NAME} UTF-8 bytes. */
    static String name(String field, String value) {
        return string(field, value, 1, WireFormat.MAX_NAME, "a name");
    }

    /**
     * Whether {@code value} is a name by {@link #name}'s rule: callers on a hot path check with it
     * first and build the field's path for {@link #name}'s message only when the rule is broken.
     */
    static boolean isName(String value) {
        if (value == null) {
            return false;
        }
        int bytes = Utf8.length(value);
        return bytes >= 1 && bytes <= WireFormat.MAX_NAME;
    }

    /** A policy URI: 1 to {@link WireFormat#MAX_URI} UTF-8 bytes. */
    static String uri(String field, String value) {
        return string(field, value, 1, WireFormat.MAX_URI, "a URI");
    }

    /** A short text: 0 to {@link WireFormat#MAX_TEXT} UTF-8 bytes. */
    static String text(String field, String value) {
        return string(field, value, 0, WireFormat.MAX_TEXT, "a text");
    }

    static String string(String field, String value, int min, int max, String what) {
        if (value == null) {
            throw new IllegalArgumentException(field + " is null; " + what + " must be " + min + " to " + max
                    + " UTF-8 bytes");
        }
        int bytes = Utf8.length(value);
        if (bytes < 0) {
            throw new IllegalArgumentException(field + " " + show(value)
                    + " holds an unpaired surrogate; it must be valid Unicode text");
        }
        if (bytes < min || bytes > max) {
            throw new IllegalArgumentException(field + " " + show(value) + " is " + bytes + " UTF-8 bytes; "
                    + what + " must be " + min + " to " + max + " bytes");
        }
        return value;
    }

    static int nonNegative(String field, int value) {
        if (value < 0) {
            throw new IllegalArgumentException(field + " is " + value + "; it must be 0 or more");
        }
        return value;
    }

    static long nonNegative(String field, long value) {
        if (value < 0) {
            throw new IllegalArgumentException(field + " is " + value + "; it must be 0 or more");
        }
        return value;
    }

    static <T> T present(String field, T value) {
        if (value == null) {
            throw new IllegalArgumentException(field + " is null; it is required");
        }
        return value;
    }

    /** An immutable copy of a list of at most {@code max} non-null elements. */
    static <T> List<T> list(String field, List<T> value, int max) {
        present(field, value);
        if (value.size() > max) {
            throw new IllegalArgumentException(field + " has " + value.size() + " elements; at most " + max
                    + " are allowed");
        }
        for (int i = 0; i < value.size(); i++) {
            if (value.get(i) == null) {
                throw new IllegalArgumentException(field + "[" + i + "] is null; elements are required");
            }
        }
        return List.copyOf(value);
    }

    /** A value for an error message: quoted, and cut to 40 characters. */
    static String show(String value) {
        return "'" + (value.length() <= 40 ? value : value.substring(0, 40) + "...") + "'";
    }
}
