package net.smc.core.capability;

import java.util.List;

/**
 * The capability description of one task (the paper's Table V): its name and the operations and
 * events of its task interface. An empty description has no operations and no events.
 */
public record TaskDescription(String task, List<OperationDescription> operations, List<EventDescription> events) {
    public TaskDescription {
        operations = List.copyOf(operations);
        events = List.copyOf(events);
    }

    public static TaskDescription empty(String task) {
        return new TaskDescription(task, List.of(), List.of());
    }

    public boolean isEmpty() {
        return operations.isEmpty() && events.isEmpty();
    }
}
