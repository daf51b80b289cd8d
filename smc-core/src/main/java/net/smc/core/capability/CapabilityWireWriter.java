package net.smc.core.capability;

import java.io.ByteArrayOutputStream;
import java.nio.ByteBuffer;
import java.nio.CharBuffer;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.CharsetEncoder;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.util.Collection;

/**
 * Writes the primitives of the capability wire form (see {@link CapabilityCodec}), enforcing the
 * same limits the reader enforces, so that whatever is written can be read back. A value over a
 * limit is the writer's own mistake, so it is an {@link IllegalArgumentException} naming the field
 * and the limit.
 */
final class CapabilityWireWriter {
    private final ByteArrayOutputStream out = new ByteArrayOutputStream(128);
    private final CharsetEncoder utf8 = StandardCharsets.UTF_8.newEncoder()
            .onMalformedInput(CodingErrorAction.REPORT)
            .onUnmappableCharacter(CodingErrorAction.REPORT);
    private final CapabilityCodec.Limits limits;
    private final String what;

    CapabilityWireWriter(CapabilityCodec.Limits limits, String what) {
        this.limits = limits;
        this.what = what;
    }

    void u8(int value) {
        out.write(value);
        checkSize();
    }

    private void u16(int value) {
        out.write(value >>> 8);
        out.write(value);
        checkSize();
    }

    void string(String value, String field) {
        if (value == null) {
            throw new IllegalArgumentException(what + ": " + field + " is null");
        }
        ByteBuffer bytes;
        try {
            bytes = utf8.encode(CharBuffer.wrap(value));
        } catch (CharacterCodingException e) {
            throw new IllegalArgumentException(what + ": " + field + " is not well-formed Unicode (it has an unpaired surrogate)");
        }
        int length = bytes.remaining();
        if (length > limits.maxStringBytes()) {
            throw new IllegalArgumentException(what + ": " + field + " is " + length + " bytes of UTF-8; the limit is "
                    + limits.maxStringBytes());
        }
        u16(length);
        out.write(bytes.array(), bytes.arrayOffset() + bytes.position(), length);
        checkSize();
    }

    void count(int size, String field) {
        if (size > limits.maxCount()) {
            throw new IllegalArgumentException(what + ": " + field + " has " + size + " entries; the limit is " + limits.maxCount());
        }
        u16(size);
    }

    /** A count, then the strings; a sorted set is written in its (ascending) order. */
    void strings(Collection<String> values, String field) {
        count(values.size(), field);
        int i = 0;
        for (String v : values) {
            string(v, field + "[" + i++ + "]");
        }
    }

    private void checkSize() {
        if (out.size() > limits.maxEncodedBytes()) {
            throw new IllegalArgumentException(what + " is longer than " + limits.maxEncodedBytes()
                    + " bytes encoded, the limit");
        }
    }

    byte[] bytes() {
        return out.toByteArray();
    }
}
