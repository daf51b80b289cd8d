package net.smc.core.capability;

import java.nio.ByteBuffer;
import java.util.ArrayList;
import java.util.List;
import java.util.SortedSet;

/**
 * The wire form of capability summaries (discovery replies) and full descriptions (replies to a
 * full capability request): compact, versioned, self-delimiting and bounded, for the messaging
 * layer to carry in datagrams. Decoding is lossless ({@code decode(encode(x)).equals(x)}) and the
 * form is canonical (sets in ascending order, no repeats, strict UTF-8), so bytes that decode also
 * re-encode to exactly themselves.
 *
 * <pre>
 * summary     = 'S' version:u8 vehicle:str resources:set tasks:set
 * description = 'D' version:u8 vehicle:str resources:set count:u16 task*
 * task        = name:str count:u16 operation* count:u16 event*
 * operation   = name:str count:u16 (argumentType:str)*
 * event       = name:str count:u16 (attributeName:str attributeType:str)*
 * set         = count:u16 str*          ascending by String.compareTo, no repeats
 * str         = length:u16 UTF-8 bytes
 * </pre>
 *
 * All integers are unsigned and big-endian. {@link Limits} bounds every string, every count and the
 * whole form; the writer refuses to exceed them ({@link IllegalArgumentException}) and the reader
 * refuses input that does ({@link CapabilityFormatException}), before allocating anything for it.
 *
 * <pre>{@code
 * byte[] bytes = CapabilityCodec.STANDARD.encode(capabilities.summary());
 * CapabilitySummary back = CapabilityCodec.STANDARD.decodeSummary(bytes);
 * }</pre>
 */
public final class CapabilityCodec {
    /** The version this codec writes and the only one it reads. */
    public static final int VERSION = 1;
    static final int SUMMARY = 'S';
    static final int DESCRIPTION = 'D';

    /** A codec with the default limits. */
    public static final CapabilityCodec STANDARD = new CapabilityCodec(Limits.DEFAULT);

    private static final String SUMMARY_NAME = "capability summary";
    private static final String DESCRIPTION_NAME = "capability description";

    /**
     * Bounds on the wire form.
     *
     * @param maxStringBytes  longest string, in UTF-8 bytes (1 to 65535)
     * @param maxCount        most entries in any one list or set (1 to 65535)
     * @param maxEncodedBytes longest whole form, in bytes (at least 16)
     */
    public record Limits(int maxStringBytes, int maxCount, int maxEncodedBytes) {
        /** Names up to 255 bytes, 256 entries a list, and a form that fits a UDP datagram with room for a header. */
        public static final Limits DEFAULT = new Limits(255, 256, 60_000);

        public Limits {
            if (maxStringBytes < 1 || maxStringBytes > 0xffff) {
                throw new IllegalArgumentException("maxStringBytes is " + maxStringBytes + "; it must be 1 to 65535");
            }
            if (maxCount < 1 || maxCount > 0xffff) {
                throw new IllegalArgumentException("maxCount is " + maxCount + "; it must be 1 to 65535");
            }
            if (maxEncodedBytes < 16) {
                throw new IllegalArgumentException("maxEncodedBytes is " + maxEncodedBytes + "; it must be 16 or more");
            }
        }
    }

    private final Limits limits;

    public CapabilityCodec(Limits limits) {
        this.limits = limits;
    }

    public Limits limits() {
        return limits;
    }

    /** @throws IllegalArgumentException when a field is null, not well-formed Unicode or over a limit (named) */
    public byte[] encode(CapabilitySummary summary) {
        CapabilityWireWriter w = header(SUMMARY, SUMMARY_NAME, summary.vehicle(), summary.resources());
        w.strings(summary.tasks(), "tasks");
        return w.bytes();
    }

    /** @throws IllegalArgumentException when a field is null, not well-formed Unicode or over a limit (named) */
    public byte[] encode(CapabilityDescription description) {
        CapabilityWireWriter w = header(DESCRIPTION, DESCRIPTION_NAME, description.vehicle(), description.resources());
        List<TaskDescription> tasks = description.tasks();
        w.count(tasks.size(), "tasks");
        for (int t = 0; t < tasks.size(); t++) {
            TaskDescription task = tasks.get(t);
            String at = "tasks[" + t + "]";
            w.string(task.task(), at + ".task");
            w.count(task.operations().size(), at + ".operations");
            for (int o = 0; o < task.operations().size(); o++) {
                OperationDescription op = task.operations().get(o);
                w.string(op.name(), at + ".operations[" + o + "].name");
                w.strings(op.argumentTypes(), at + ".operations[" + o + "].argumentTypes");
            }
            w.count(task.events().size(), at + ".events");
            for (int e = 0; e < task.events().size(); e++) {
                EventDescription event = task.events().get(e);
                String ev = at + ".events[" + e + "]";
                w.string(event.name(), ev + ".name");
                w.count(event.attributes().size(), ev + ".attributes");
                for (int a = 0; a < event.attributes().size(); a++) {
                    w.string(event.attributes().get(a).name(), ev + ".attributes[" + a + "].name");
                    w.string(event.attributes().get(a).type(), ev + ".attributes[" + a + "].type");
                }
            }
        }
        return w.bytes();
    }

    private CapabilityWireWriter header(int kind, String what, String vehicle, SortedSet<String> resources) {
        CapabilityWireWriter w = new CapabilityWireWriter(limits, what);
        w.u8(kind);
        w.u8(VERSION);
        w.string(vehicle, "vehicle");
        w.strings(resources, "resources");
        return w;
    }

    /** Decodes a whole array holding exactly one summary. */
    public CapabilitySummary decodeSummary(byte[] bytes) throws CapabilityFormatException {
        ByteBuffer in = ByteBuffer.wrap(bytes);
        CapabilitySummary s = readSummary(in);
        requireEnd(in, SUMMARY_NAME, bytes.length);
        return s;
    }

    /** Decodes a whole array holding exactly one description. */
    public CapabilityDescription decodeDescription(byte[] bytes) throws CapabilityFormatException {
        ByteBuffer in = ByteBuffer.wrap(bytes);
        CapabilityDescription d = readDescription(in);
        requireEnd(in, DESCRIPTION_NAME, bytes.length);
        return d;
    }

    /**
     * Reads one summary from the buffer's position, which moves past it on success and stays put on
     * an error; bytes after it are left for the caller (the form delimits itself).
     */
    public CapabilitySummary readSummary(ByteBuffer buffer) throws CapabilityFormatException {
        ByteBuffer in = buffer.duplicate();   // big-endian, whatever the caller's order
        CapabilityWireReader r = new CapabilityWireReader(in, limits, SUMMARY_NAME);
        readHeader(r, SUMMARY);
        String vehicle = r.string("vehicle");
        SortedSet<String> resources = r.sortedSet("resources");
        SortedSet<String> tasks = r.sortedSet("tasks");
        buffer.position(in.position());
        return new CapabilitySummary(vehicle, resources, tasks);
    }

    /** Reads one description from the buffer's position, as {@link #readSummary(ByteBuffer)} does. */
    public CapabilityDescription readDescription(ByteBuffer buffer) throws CapabilityFormatException {
        ByteBuffer in = buffer.duplicate();
        CapabilityWireReader r = new CapabilityWireReader(in, limits, DESCRIPTION_NAME);
        readHeader(r, DESCRIPTION);
        String vehicle = r.string("vehicle");
        SortedSet<String> resources = r.sortedSet("resources");
        int taskCount = r.count("tasks");
        List<TaskDescription> tasks = new ArrayList<>();
        for (int t = 0; t < taskCount; t++) {
            tasks.add(readTask(r, "tasks[" + t + "]"));
        }
        buffer.position(in.position());
        return new CapabilityDescription(vehicle, resources, tasks);
    }

    private static TaskDescription readTask(CapabilityWireReader r, String at) throws CapabilityFormatException {
        String name = r.string(at + ".task");
        int opCount = r.count(at + ".operations");
        List<OperationDescription> ops = new ArrayList<>();
        for (int o = 0; o < opCount; o++) {
            String op = at + ".operations[" + o + "]";
            ops.add(new OperationDescription(r.string(op + ".name"), r.strings(op + ".argumentTypes")));
        }
        int eventCount = r.count(at + ".events");
        List<EventDescription> events = new ArrayList<>();
        for (int e = 0; e < eventCount; e++) {
            String ev = at + ".events[" + e + "]";
            String eventName = r.string(ev + ".name");
            int attrCount = r.count(ev + ".attributes");
            List<EventDescription.Attribute> attributes = new ArrayList<>();
            for (int a = 0; a < attrCount; a++) {
                String attr = ev + ".attributes[" + a + "]";
                attributes.add(new EventDescription.Attribute(r.string(attr + ".name"), r.string(attr + ".type")));
            }
            events.add(new EventDescription(eventName, attributes));
        }
        return new TaskDescription(name, ops, events);
    }

    private static void readHeader(CapabilityWireReader r, int kind) throws CapabilityFormatException {
        int found = r.u8("kind");
        if (found != kind) {
            String seen = found == SUMMARY ? "a " + SUMMARY_NAME : found == DESCRIPTION ? "a " + DESCRIPTION_NAME
                    : String.format("0x%02x", found);
            throw r.error(0, "kind", "expected '" + (char) kind + "', found " + seen);
        }
        int version = r.u8("version");
        if (version != VERSION) {
            throw r.error(1, "version", "version " + version + " is not supported; this reader knows version " + VERSION);
        }
    }

    private static void requireEnd(ByteBuffer in, String what, int length) throws CapabilityFormatException {
        if (in.hasRemaining()) {
            throw new CapabilityFormatException(what + ": " + in.remaining() + " bytes after the end of the form at byte "
                    + in.position() + " of " + length, in.position());
        }
    }
}
