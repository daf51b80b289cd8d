package net.smc.core.capability;

import java.nio.ByteBuffer;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.CharsetDecoder;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.SortedSet;
import java.util.TreeSet;

/**
 * Reads the primitives of the capability wire form (see {@link CapabilityCodec}) from a buffer that
 * may hold anything. Every length and count is checked against the limits and against the bytes
 * left before anything is allocated, so hostile input costs at most what it weighs.
 */
final class CapabilityWireReader {
    private final ByteBuffer in;
    private final int start;
    private final CapabilityCodec.Limits limits;
    private final String what;
    private final CharsetDecoder utf8 = StandardCharsets.UTF_8.newDecoder()
            .onMalformedInput(CodingErrorAction.REPORT)
            .onUnmappableCharacter(CodingErrorAction.REPORT);

    CapabilityWireReader(ByteBuffer in, CapabilityCodec.Limits limits, String what) {
        this.in = in;
        this.start = in.position();
        this.limits = limits;
        this.what = what;
    }

    int u8(String field) throws CapabilityFormatException {
        need(1, field);
        return in.get() & 0xff;
    }

    private int u16(String field) throws CapabilityFormatException {
        need(2, field);
        return in.getShort() & 0xffff;
    }

    String string(String field) throws CapabilityFormatException {
        int at = offset();
        int length = u16(field);
        if (length > limits.maxStringBytes()) {
            throw error(at, field, "a string of " + length + " bytes; the limit is " + limits.maxStringBytes());
        }
        need(length, field);
        try {
            String s = utf8.decode(in.slice(in.position(), length)).toString();
            in.position(in.position() + length);
            return s;
        } catch (CharacterCodingException e) {
            throw error(at, field, "not valid UTF-8");
        }
    }

    int count(String field) throws CapabilityFormatException {
        int at = offset();
        int n = u16(field);
        if (n > limits.maxCount()) {
            throw error(at, field, n + " entries; the limit is " + limits.maxCount());
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
                throw error(at, field + "[" + i + "]", "'" + s + "' does not come after '" + previous
                        + "'; a set is written in ascending order without repeats");
            }
            values.add(s);
            previous = s;
        }
        return Collections.unmodifiableSortedSet(values);
    }

    int offset() {
        return in.position() - start;
    }

    CapabilityFormatException error(int at, String field, String rule) {
        return new CapabilityFormatException(what + ": " + field + " at byte " + at + ": " + rule, at);
    }

    private void need(int n, String field) throws CapabilityFormatException {
        if (in.remaining() < n) {
            throw error(offset(), field, "truncated: needs " + n + " bytes, " + in.remaining() + " left");
        }
        if (offset() + n > limits.maxEncodedBytes()) {
            throw error(offset(), field, "the form is longer than the limit of " + limits.maxEncodedBytes() + " bytes");
        }
    }
}
