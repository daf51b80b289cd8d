package net.smc.core.message;

import java.util.Collection;
import net.smc.core.capability.CapabilityDescription;
import net.smc.core.capability.CapabilitySummary;
import net.smc.core.capability.EventDescription;
import net.smc.core.capability.OperationDescription;
import net.smc.core.capability.TaskDescription;

/**
 * Wire limits for the capability records of {@code net.smc.core.capability}, which are shared with
 * the rest of the cell and check nothing about sizes themselves: every name 1 to 64 bytes, at most
 * 64 resources and 64 tasks, 64 operations and 64 events per task, 16 arguments per operation and
 * 16 attributes per event.
 *
 * <p>Every discovery reply and capability reply is checked (a team of 1,000 builds tens of thousands
 * per run), so the path of a field ({@code CapabilityReply.description.tasks[0].task}) is built only
 * when its rule is broken, for the message; a valid record costs the checks alone.
 */
final class CapabilityLimits {
    private CapabilityLimits() {
    }

    static CapabilitySummary summary(String field, CapabilitySummary s) {
        Fields.present(field, s);
        name(field, ".vehicle", s.vehicle());
        names(field, ".resources", s.resources(), WireFormat.MAX_RESOURCES);
        names(field, ".tasks", s.tasks(), WireFormat.MAX_TASKS);
        return s;
    }

    static CapabilityDescription description(String field, CapabilityDescription d) {
        Fields.present(field, d);
        name(field, ".vehicle", d.vehicle());
        names(field, ".resources", d.resources(), WireFormat.MAX_RESOURCES);
        count(field, ".tasks", d.tasks(), WireFormat.MAX_TASKS);
        for (int i = 0; i < d.tasks().size(); i++) {
            task(field, i, d.tasks().get(i));
        }
        return d;
    }

    private static void task(String parent, int index, TaskDescription t) {
        if (!valid(t)) {
            checkTask(parent + ".tasks[" + index + "]", t);   // throws, naming the field
        }
    }

    /** Whether every rule {@link #checkTask} applies holds, without building a field's path. */
    private static boolean valid(TaskDescription t) {
        if (!Fields.isName(t.task()) || t.operations().size() > WireFormat.MAX_OPERATIONS
                || t.events().size() > WireFormat.MAX_OPERATIONS) {
            return false;
        }
        for (OperationDescription op : t.operations()) {
            if (!Fields.isName(op.name()) || !validNames(op.argumentTypes(), WireFormat.MAX_ARGUMENTS)) {
                return false;
            }
        }
        for (EventDescription e : t.events()) {
            if (!Fields.isName(e.name()) || e.attributes().size() > WireFormat.MAX_ARGUMENTS) {
                return false;
            }
            for (int k = 0; k < e.attributes().size(); k++) {
                if (!Fields.isName(e.attributes().get(k).name()) || !Fields.isName(e.attributes().get(k).type())) {
                    return false;
                }
            }
        }
        return true;
    }

    /** Checks a task rule by rule, naming the first field that breaks one. */
    private static void checkTask(String field, TaskDescription t) {
        Fields.name(field + ".task", t.task());
        count(field, ".operations", t.operations(), WireFormat.MAX_OPERATIONS);
        for (int i = 0; i < t.operations().size(); i++) {
            OperationDescription op = t.operations().get(i);
            String f = field + ".operations[" + i + "]";
            Fields.name(f + ".name", op.name());
            names(f, ".argumentTypes", op.argumentTypes(), WireFormat.MAX_ARGUMENTS);
        }
        count(field, ".events", t.events(), WireFormat.MAX_OPERATIONS);
        for (int i = 0; i < t.events().size(); i++) {
            EventDescription e = t.events().get(i);
            String f = field + ".events[" + i + "]";
            Fields.name(f + ".name", e.name());
            count(f, ".attributes", e.attributes(), WireFormat.MAX_ARGUMENTS);
            for (int k = 0; k < e.attributes().size(); k++) {
                Fields.name(f + ".attributes[" + k + "].name", e.attributes().get(k).name());
                Fields.name(f + ".attributes[" + k + "].type", e.attributes().get(k).type());
            }
        }
    }

    private static boolean validNames(Collection<String> names, int max) {
        if (names.size() > max) {
            return false;
        }
        for (String n : names) {
            if (!Fields.isName(n)) {
                return false;
            }
        }
        return true;
    }

    /** The name at {@code parent + part}; the path is built only for a broken rule's message. */
    private static void name(String parent, String part, String value) {
        if (!Fields.isName(value)) {
            Fields.name(parent + part, value);
        }
    }

    private static void names(String parent, String part, Collection<String> names, int max) {
        if (validNames(names, max)) {
            return;
        }
        String field = parent + part;
        count(field, "", names, max);
        int i = 0;
        for (String n : names) {
            Fields.name(field + "[" + i++ + "]", n);
        }
    }

    private static void count(String parent, String part, Collection<?> c, int max) {
        if (c.size() > max) {
            throw new IllegalArgumentException(parent + part + " has " + c.size() + " elements; at most " + max
                    + " are allowed");
        }
    }
}
