package net.smc.core.role;

/**
 * An operation of one of a role's tasks: the task's name in the role and the PonderTalk selector
 * ({@code goTo:y:}). The local interface lists them; the external interface exports some.
 */
public record TaskOperation(String task, String selector) {
    public TaskOperation {
        RoleNames.check("task name of an operation", task);
        RoleNames.checkSelector("selector of an operation of task '" + task + "'", selector);
    }
}
