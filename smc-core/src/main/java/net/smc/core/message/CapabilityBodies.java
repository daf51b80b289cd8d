package net.smc.core.message;

import java.nio.ByteBuffer;
import net.smc.core.capability.CapabilityDescription;
import net.smc.core.capability.CapabilityFormatException;
import net.smc.core.capability.CapabilitySummary;
import net.smc.core.wire.ByteWriter;

/**
 * Capability summaries and descriptions on the wire: the capability package's own self-delimiting
 * form ({@link net.smc.core.capability.CapabilityCodec}), embedded as it is, with the message
 * layer's limits on names and counts. One encoding of a capability form serves everywhere.
 */
final class CapabilityBodies {
    /** The capability forms within this wire format's limits. */
    private static final net.smc.core.capability.CapabilityCodec FORMS = new net.smc.core.capability.CapabilityCodec(
            new net.smc.core.capability.CapabilityCodec.Limits(WireFormat.MAX_NAME, WireFormat.MAX_TASKS,
                    WireFormat.MAX_PAYLOAD - 1_024));

    private CapabilityBodies() {
    }

    static void writeSummary(CapabilitySummary s, ByteWriter w) {
        w.bytes(FORMS.encode(s));
    }

    static CapabilitySummary readSummary(DatagramReader r) throws DecodeException {
        return read(r, "summary", FORMS::readSummary);
    }

    static void writeDescription(CapabilityDescription d, ByteWriter w) {
        w.bytes(FORMS.encode(d));
    }

    static CapabilityDescription readDescription(DatagramReader r) throws DecodeException {
        return read(r, "description", FORMS::readDescription);
    }

    /** Reads one capability form of the given kind at the reader's position, moving past it. */
    private interface FormReader<T> {
        T read(ByteBuffer form) throws CapabilityFormatException;
    }

    private static <T> T read(DatagramReader r, String field, FormReader<T> reader) throws DecodeException {
        ByteBuffer form = ByteBuffer.wrap(r.array(), r.position(), r.remaining());
        try {
            T value = reader.read(form);
            r.take(form.position() - r.position(), field);
            return value;
        } catch (CapabilityFormatException e) {
            RejectReason reason = switch (e.problem()) {
                case TRUNCATED -> RejectReason.TRUNCATED;
                case OVERSIZED -> RejectReason.OVERSIZED;
                case MALFORMED -> RejectReason.MALFORMED;
            };
            throw new DecodeException(reason, field + ": " + e.getMessage());
        }
    }
}
