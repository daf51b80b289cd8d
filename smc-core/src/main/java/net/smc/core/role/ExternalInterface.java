package net.smc.core.role;

import java.util.HashSet;
import java.util.List;
import java.util.Set;

/**
 * What a role offers to and needs from collaborating roles on other vehicles (the paper's section
 * II-B.2.A). Every invocation through it, on behalf of another role, passes the receiving role's
 * authorisation policies ({@link ExternalGateway}).
 *
 * <ol>
 *   <li>management operations, common to all roles: {@link #MANAGEMENT_OPERATIONS}, answered by
 *       the role object {@code root/role/<name>};</li>
 *   <li>{@code exported}: operations of the role's tasks made visible to other roles (each must be in
 *       the local interface);</li>
 *   <li>{@code published}: events the role publishes for other roles (each must be in the local
 *       interface);</li>
 *   <li>{@code requiredOperations}: operations the role expects collaborating roles to export;</li>
 *   <li>{@code requiredEvents}: events of collaborating roles the role reacts to; only these may be
 *       raised in the cell on another role's behalf.</li>
 * </ol>
 */
public record ExternalInterface(List<TaskOperation> exported, List<String> published,
                                List<RequiredOperation> requiredOperations, List<String> requiredEvents) {

    /** The role object's operations, common to every role; see {@code RoleObject}. */
    public static final Set<String> MANAGEMENT_OPERATIONS =
            Set.of("name", "manages", "policies", "authorisations", "tasks", "isEnabled:", "enable:", "disable:");

    /** Nothing exported, published or required. */
    public static final ExternalInterface NONE = new ExternalInterface(List.of(), List.of(), List.of(), List.of());

    public ExternalInterface {
        exported = List.copyOf(exported);
        published = List.copyOf(published);
        requiredOperations = List.copyOf(requiredOperations);
        requiredEvents = List.copyOf(requiredEvents);
        Set<String> selectors = new HashSet<>();
        for (TaskOperation op : exported) {
            if (MANAGEMENT_OPERATIONS.contains(op.selector())) {
                throw new IllegalArgumentException("exported operation '" + op.selector() + "' of task '" + op.task()
                        + "' has the name of a management operation common to all roles; rename it");
            }
            if (!selectors.add(op.selector())) {
                throw new IllegalArgumentException("operation '" + op.selector()
                        + "' is exported twice; a caller names an operation by its selector alone, so it must be unique");
            }
        }
        published.forEach(e -> RoleNames.check("published event", e));
        requiredEvents.forEach(e -> RoleNames.check("required event", e));
    }

    /** The exported operation with this selector, or {@code null}. */
    public TaskOperation exportedOperation(String selector) {
        for (TaskOperation op : exported) {
            if (op.selector().equals(selector)) {
                return op;
            }
        }
        return null;
    }

    /** The management operations, the first part of every role's external interface. */
    public Set<String> managementOperations() {
        return MANAGEMENT_OPERATIONS;
    }
}
