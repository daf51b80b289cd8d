package net.smc.core.capability;

import java.nio.ByteBuffer;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.SortedSet;
import java.util.TreeSet;
import net.smc.core.wire.ByteReader;
import net.smc.core.wire.StrictUtf8;
import net.smc.core.wire.WireErrors;
import net.smc.core.wire.WireProblem;

/**
 * The capability wire form's fields (see {@link CapabilityCodec}) on top of the shared
 * {@link ByteReader}: strings, counts, lists and canonical sets. Every length and count is checked
 * against the limits and against the bytes left before anything is allocated, so hostile input costs
 * at most what it weighs. Errors read "FORM: FIELD at byte N: RULE".
 */
final class CapabilityReader extends ByteReader<CapabilityFormatException> {
    private final CapabilityCodec.Limits limits;

    private CapabilityReader(Errors errors, byte[] bytes, int start, int end, CapabilityCodec.Limits limits) {
        super(errors, bytes, start, end);
        this.limits = limits;
    }

    /**
     * Reads from {@code in}'s position to its limit, leaving {@code in} alone (its position moves
     * only when the caller moves it by {@link #offset()}). The reader sees at most
     * {@code limits.maxEncodedBytes()}: a field past them breaks that limit rather than being short.
     */
    static CapabilityReader of(ByteBuffer in, CapabilityCodec.Limits limits, String what) {
        int available = in.remaining();
        int visible = Math.min(available, limits.maxEncodedBytes());
        Errors errors = new Errors(what, available, limits.maxEncodedBytes());
        if (in.hasArray()) {
            int start = in.arrayOffset() + in.position();
            return new CapabilityReader(errors, in.array(), start, start + visible, limits);
        }
        byte[] copy = new byte[visible];
        in.get(in.position(), copy, 0, visible);
        return new CapabilityReader(errors, copy, 0, visible, limits);
    }

    String string(String field) throws CapabilityFormatException {
        int at = offset();
        int length = length16(field);
        if (length > limits.maxStringBytes()) {
            throw error(WireProblem.OVERSIZED, at, field, "a string of " + length + " bytes; the limit is "
                    + limits.maxStringBytes());
        }
        int from = take(length, field);
        if (!StrictUtf8.isWellFormed(array(), from, length)) {
            throw error(WireProblem.MALFORMED, at, field, "not valid UTF-8");
        }
        return StrictUtf8.decode(array(), from, length);
    }

    int count(String field) throws CapabilityFormatException {
        int at = offset();
        int n = length16(field);
        if (n > limits.maxCount()) {
            throw error(WireProblem.OVERSIZED, at, field, n + " entries; the limit is " + limits.maxCount());
        }
        return n;
    }

    List<String> strings(String field) throws CapabilityFormatException {
        int n = count(field);
        List<String> values = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            values.add(string(field + "[" + i + "]"));
        }
        return values;
    }

    /** A set is written in ascending order without repeats, so every set has exactly one form. */
    SortedSet<String> sortedSet(String field) throws CapabilityFormatException {
        int n = count(field);
        TreeSet<String> values = new TreeSet<>();
        String previous = null;
        for (int i = 0; i < n; i++) {
            int at = offset();
            String s = string(field + "[" + i + "]");
            if (previous != null && s.compareTo(previous) <= 0) {
                throw error(WireProblem.MALFORMED, at, field + "[" + i + "]", "'" + s + "' does not come after '"
                        + previous + "'; a set is written in ascending order without repeats");
            }
            values.add(s);
            previous = s;
        }
        return Collections.unmodifiableSortedSet(values);
    }

    /**
     * The form's wording. The reader's range stops at the size limit, so a shortage there is told
     * apart from a truncated form by the bytes that were really available.
     */
    private record Errors(String what, int available, int maxEncodedBytes) implements WireErrors<CapabilityFormatException> {
        @Override
        public CapabilityFormatException error(WireProblem problem, int offset, String field, String rule) {
            return new CapabilityFormatException(what + ": " + field + " at byte " + offset + ": " + rule, offset, problem);
        }

        @Override
        public CapabilityFormatException truncated(int offset, String field, int needed, int left) {
            if ((long) offset + needed > available) {
                return WireErrors.super.truncated(offset, field, needed, available - offset);
            }
            return error(WireProblem.OVERSIZED, offset, field, "the form is longer than the limit of "
                    + maxEncodedBytes + " bytes");
        }
    }
}
