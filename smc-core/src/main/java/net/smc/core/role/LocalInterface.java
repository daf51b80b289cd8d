package net.smc.core.role;

import java.util.List;

/**
 * What the vehicle's own tasks offer to the role's policies (the paper's section II-B.2.B): the
 * events the tasks raise (they trigger role-mission policies, or are published through the
 * external interface) and the operations the tasks implement. The Role-Manager checks, when it
 * loads the role, that each task understands the operations listed for it.
 */
public record LocalInterface(List<TaskOperation> operations, List<String> events) {

    /** No operations and no events. */
    public static final LocalInterface NONE = new LocalInterface(List.of(), List.of());

    public LocalInterface {
        operations = List.copyOf(operations);
        events = List.copyOf(events);
        events.forEach(e -> RoleNames.check("local event", e));
    }
}
