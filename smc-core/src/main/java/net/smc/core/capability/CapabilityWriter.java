package net.smc.core.capability;

import java.util.Collection;
import net.smc.core.wire.ByteWriter;
import net.smc.core.wire.StrictUtf8;

/**
 * The capability wire form's fields (see {@link CapabilityCodec}) on top of the shared
 * {@link ByteWriter}, enforcing the same limits {@link CapabilityReader} enforces, so that whatever
 * is written can be read back. A value over a limit is the writer's own mistake, so it is an
 * {@link IllegalArgumentException} naming the field and the limit.
 */
final class CapabilityWriter {
    private final ByteWriter out;
    private final CapabilityCodec.Limits limits;
    private final String what;

    CapabilityWriter(CapabilityCodec.Limits limits, String what) {
        this.limits = limits;
        this.what = what;
        int max = limits.maxEncodedBytes();
        this.out = ByteWriter.growing(128, max, () -> new IllegalArgumentException(what + " is longer than " + max
                + " bytes encoded, the limit"));
    }

    void u8(int value) {
        out.u8(value);
    }

    void string(String value, String field) {
        if (value == null) {
            throw new IllegalArgumentException(what + ": " + field + " is null");
        }
        int length = StrictUtf8.length(value);
        if (length < 0) {
            throw new IllegalArgumentException(what + ": " + field + " is not well-formed Unicode (it has an unpaired surrogate)");
        }
        if (length > limits.maxStringBytes()) {
            throw new IllegalArgumentException(what + ": " + field + " is " + length + " bytes of UTF-8; the limit is "
                    + limits.maxStringBytes());
        }
        out.string16(value, length);
    }

    void count(int size, String field) {
        if (size > limits.maxCount()) {
            throw new IllegalArgumentException(what + ": " + field + " has " + size + " entries; the limit is " + limits.maxCount());
        }
        out.u16(size);
    }

    /** A count, then the strings; a sorted set is written in its (ascending) order. */
    void strings(Collection<String> values, String field) {
        count(values.size(), field);
        int i = 0;
        for (String v : values) {
            string(v, field + "[" + i++ + "]");
        }
    }

    byte[] bytes() {
        return out.toByteArray();
    }
}
