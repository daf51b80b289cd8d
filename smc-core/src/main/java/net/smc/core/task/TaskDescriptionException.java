package net.smc.core.task;

/**
 * A task cannot be described: one of its task interfaces names another task (Table V's "return
 * error"), or an event of it cannot become an event template (an attribute without a name, a
 * name that is not a PonderTalk identifier, two events or attributes of one name). The message
 * names the task, the interface or method, and the rule. Checked, because a vehicle must refuse to
 * load such a task rather than advertise a wrong capability.
 */
public final class TaskDescriptionException extends Exception {
    private static final long serialVersionUID = 1L;

    public TaskDescriptionException(String message) {
        super(message);
    }
}
