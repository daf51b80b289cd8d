package net.smc.core.message;

import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.SortedSet;
import java.util.TreeSet;
import net.smc.core.capability.CapabilityDescription;
import net.smc.core.capability.CapabilitySummary;
import net.smc.core.capability.EventDescription;
import net.smc.core.capability.OperationDescription;
import net.smc.core.capability.TaskDescription;

/**
 * Capability summaries and descriptions on the wire. Sets (resources, task names) are written in
 * their sorted order and must arrive strictly increasing, so each set has one encoding; lists
 * (tasks, operations, events, their argument types and attributes) keep their order.
 * <pre>
 *   summary     = vehicle name, resources set, tasks set
 *   description = vehicle name, resources set, count 1, task*
 *   task        = name, count 1, (name, count 1, type name*)*      operations
 *                       count 1, (name, count 1, (name, type name)*)*  events
 *   set         = count 1, name*   (strictly increasing)
 * </pre>
 */
final class CapabilityCodec {
    private CapabilityCodec() {
    }

    static void writeSummary(CapabilitySummary s, WireWriter w) {
        w.string8(s.vehicle());
        writeNames(s.resources(), w);
        writeNames(s.tasks(), w);
    }

    static CapabilitySummary readSummary(WireReader r) throws DecodeException {
        String vehicle = r.name("summary.vehicle");
        SortedSet<String> resources = readSet(r, "summary.resources", WireFormat.MAX_RESOURCES);
        SortedSet<String> tasks = readSet(r, "summary.tasks", WireFormat.MAX_TASKS);
        return new CapabilitySummary(vehicle, resources, tasks);
    }

    static void writeDescription(CapabilityDescription d, WireWriter w) {
        w.string8(d.vehicle());
        writeNames(d.resources(), w);
        w.u8(d.tasks().size());
        for (TaskDescription t : d.tasks()) {
            w.string8(t.task());
            w.u8(t.operations().size());
            for (OperationDescription op : t.operations()) {
                w.string8(op.name());
                writeNames(op.argumentTypes(), w);
            }
            w.u8(t.events().size());
            for (EventDescription e : t.events()) {
                w.string8(e.name());
                w.u8(e.attributes().size());
                for (EventDescription.Attribute a : e.attributes()) {
                    w.string8(a.name());
                    w.string8(a.type());
                }
            }
        }
    }

    static CapabilityDescription readDescription(WireReader r) throws DecodeException {
        String vehicle = r.name("description.vehicle");
        SortedSet<String> resources = readSet(r, "description.resources", WireFormat.MAX_RESOURCES);
        int n = r.count("description.tasks", WireFormat.MAX_TASKS, 3);
        List<TaskDescription> tasks = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
            tasks.add(readTask(r));
        }
        return new CapabilityDescription(vehicle, resources, tasks);
    }

    private static TaskDescription readTask(WireReader r) throws DecodeException {
        String name = r.name("task name");
        int nOps = r.count("task operations", WireFormat.MAX_OPERATIONS, 2);
        List<OperationDescription> ops = new ArrayList<>(nOps);
        for (int i = 0; i < nOps; i++) {
            String op = r.name("operation name");
            ops.add(new OperationDescription(op, readNames(r, "operation argument types", WireFormat.MAX_ARGUMENTS)));
        }
        int nEvents = r.count("task events", WireFormat.MAX_OPERATIONS, 2);
        List<EventDescription> events = new ArrayList<>(nEvents);
        for (int i = 0; i < nEvents; i++) {
            String event = r.name("event name");
            int nAttrs = r.count("event attributes", WireFormat.MAX_ARGUMENTS, 2);
            List<EventDescription.Attribute> attrs = new ArrayList<>(nAttrs);
            for (int k = 0; k < nAttrs; k++) {
                String attr = r.name("attribute name");
                attrs.add(new EventDescription.Attribute(attr, r.name("attribute type")));
            }
            events.add(new EventDescription(event, attrs));
        }
        return new TaskDescription(name, ops, events);
    }

    private static void writeNames(Collection<String> names, WireWriter w) {
        w.u8(names.size());
        for (String n : names) {
            w.string8(n);
        }
    }

    private static List<String> readNames(WireReader r, String field, int max) throws DecodeException {
        int n = r.count(field, max, 1);
        List<String> names = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
            names.add(r.name(field));
        }
        return names;
    }

    private static SortedSet<String> readSet(WireReader r, String field, int max) throws DecodeException {
        int n = r.count(field, max, 1);
        TreeSet<String> set = new TreeSet<>();
        String previous = null;
        for (int i = 0; i < n; i++) {
            String name = r.name(field);
            if (previous != null && previous.compareTo(name) >= 0) {
                throw new DecodeException(RejectReason.MALFORMED, field + " is not strictly increasing: '" + name
                        + "' follows '" + previous + "'");
            }
            set.add(name);
            previous = name;
        }
        return set;
    }
}
