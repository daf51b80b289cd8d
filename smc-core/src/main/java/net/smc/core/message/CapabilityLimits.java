package net.smc.core.message;

import java.util.Collection;
import java.util.List;
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
 */
final class CapabilityLimits {
    private CapabilityLimits() {
    }

    static CapabilitySummary summary(String field, CapabilitySummary s) {
        Fields.present(field, s);
        Fields.name(field + ".vehicle", s.vehicle());
        names(field + ".resources", s.resources(), WireFormat.MAX_RESOURCES);
        names(field + ".tasks", s.tasks(), WireFormat.MAX_TASKS);
        return s;
    }

    static CapabilityDescription description(String field, CapabilityDescription d) {
        Fields.present(field, d);
        Fields.name(field + ".vehicle", d.vehicle());
        names(field + ".resources", d.resources(), WireFormat.MAX_RESOURCES);
        count(field + ".tasks", d.tasks(), WireFormat.MAX_TASKS);
        for (int i = 0; i < d.tasks().size(); i++) {
            task(field + ".tasks[" + i + "]", d.tasks().get(i));
        }
        return d;
    }

    private static void task(String field, TaskDescription t) {
        Fields.name(field + ".task", t.task());
        count(field + ".operations", t.operations(), WireFormat.MAX_OPERATIONS);
        for (int i = 0; i < t.operations().size(); i++) {
            OperationDescription op = t.operations().get(i);
            String f = field + ".operations[" + i + "]";
            Fields.name(f + ".name", op.name());
            names(f + ".argumentTypes", op.argumentTypes(), WireFormat.MAX_ARGUMENTS);
        }
        count(field + ".events", t.events(), WireFormat.MAX_OPERATIONS);
        for (int i = 0; i < t.events().size(); i++) {
            EventDescription e = t.events().get(i);
            String f = field + ".events[" + i + "]";
            Fields.name(f + ".name", e.name());
            count(f + ".attributes", e.attributes(), WireFormat.MAX_ARGUMENTS);
            for (int k = 0; k < e.attributes().size(); k++) {
                Fields.name(f + ".attributes[" + k + "].name", e.attributes().get(k).name());
                Fields.name(f + ".attributes[" + k + "].type", e.attributes().get(k).type());
            }
        }
    }

    private static void names(String field, Collection<String> names, int max) {
        count(field, names, max);
        int i = 0;
        for (String n : names) {
            Fields.name(field + "[" + i++ + "]", n);
        }
    }

    private static void count(String field, Collection<?> c, int max) {
        if (c.size() > max) {
            throw new IllegalArgumentException(field + " has " + c.size() + " elements; at most " + max
                    + " are allowed");
        }
    }
}
