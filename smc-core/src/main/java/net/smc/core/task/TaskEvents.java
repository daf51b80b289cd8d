package net.smc.core.task;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import net.smc.core.capability.EventDescription;
import net.smc.core.capability.TaskDescription;
import net.smc.policy.PolicyEngine;
import net.smc.policy.api.DomainHandle;
import net.smc.policy.api.EventHandle;
import net.smc.policy.api.Handle;

/**
 * A task's binding to one cell: where it sits ({@code root/task/<task>}) and the event template of
 * each of its {@link TaskEvent}s.
 *
 * <p>Event templates are flat, {@code root/event/<event>}, not {@code root/event/<task>/<event>}:
 * the paper's policies name events that way ({@code /event/newUAV}, {@code /event/UAVFailure}), a
 * policy should not care which task raised an event, and two tasks may raise the same event. A
 * template that already exists (made by a policy file, or by another task) is reused when its
 * attribute names are the event's, in order; otherwise binding fails, since policies bind
 * parameters by those names.
 */
final class TaskEvents {
    static final String EVENTS = "event";
    static final String TASKS = "task";

    private final PolicyEngine cell;
    private final Task task;
    private final String taskName;
    private final Map<String, EventHandle> templates;

    private TaskEvents(PolicyEngine cell, Task task, String taskName, Map<String, EventHandle> templates) {
        this.cell = cell;
        this.task = task;
        this.taskName = taskName;
        this.templates = templates;
    }

    /** Checks every path first and changes the cell only when all of them are free or compatible. */
    static TaskEvents bind(Task task, PolicyEngine cell) throws TaskDescriptionException {
        TaskDescription description = task.describe();
        if (!TaskDescriber.isIdentifier(description.task())) {
            throw new IllegalStateException("task class " + task.getClass().getName() + " has the name '" + description.task()
                    + "', which is not a PonderTalk identifier (a letter, then letters, digits or _), so it cannot be"
                    + " root/" + TASKS + "/<name>");
        }
        Handle handle = task.managed();
        DomainHandle root = cell.root();
        DomainHandle eventDomain = domainAt(root, EVENTS);
        Object taskDomain = root.get(TASKS);
        if (taskDomain != null && !(taskDomain instanceof DomainHandle)) {
            throw occupied("root/" + TASKS, taskDomain, "a domain");
        }
        Object sitting = taskDomain instanceof DomainHandle d ? d.get(description.task()) : null;
        if (sitting != null && sitting != handle) {
            throw occupied("root/" + TASKS + "/" + description.task(), sitting, "this task");
        }
        Map<String, EventHandle> templates = new LinkedHashMap<>();
        List<EventDescription> missing = new ArrayList<>();
        for (EventDescription event : description.events()) {
            Object existing = eventDomain == null ? null : eventDomain.get(event.name());
            List<String> names = event.attributes().stream().map(EventDescription.Attribute::name).toList();
            if (existing == null) {
                missing.add(event);
            } else if (existing instanceof EventHandle t && t.attributeNames().equals(names)) {
                templates.put(event.name(), t);
            } else if (existing instanceof EventHandle t) {
                throw new IllegalStateException("cannot bind task " + description.task() + ": root/" + EVENTS + "/"
                        + event.name() + " is an event template with attributes " + t.attributeNames() + ", but the task's event '"
                        + event.name() + "' has " + names + "; an event's attribute names must match its template's");
            } else {
                throw occupied("root/" + EVENTS + "/" + event.name(), existing, "an event template");
            }
        }
        // Nothing can fail from here on.
        if (eventDomain == null) {
            eventDomain = cell.newDomain();
            root.put(EVENTS, eventDomain);
        }
        for (EventDescription event : missing) {
            EventHandle t = cell.newEventTemplate(
                    event.attributes().stream().map(EventDescription.Attribute::name).toList());
            eventDomain.put(event.name(), t);
            templates.put(event.name(), t);
        }
        if (!(taskDomain instanceof DomainHandle)) {
            taskDomain = cell.newDomain();
            root.put(TASKS, taskDomain);
        }
        ((DomainHandle) taskDomain).put(description.task(), handle);
        return new TaskEvents(cell, task, description.task(), templates);
    }

    private static DomainHandle domainAt(DomainHandle root, String name) {
        Object found = root.get(name);
        if (found != null && !(found instanceof DomainHandle)) {
            throw occupied("root/" + name, found, "a domain");
        }
        return (DomainHandle) found;
    }

    private static IllegalStateException occupied(String path, Object found, String wanted) {
        return new IllegalStateException(path + " holds " + PolicyEngine.print(found) + ", not " + wanted
                + "; a task needs that path to be free or to hold " + wanted);
    }

    PolicyEngine cell() {
        return cell;
    }

    boolean raise(String event, Object[] values) {
        EventHandle template = templates.get(event);
        if (template == null) {
            throw new IllegalArgumentException("task " + taskName + " has no event '" + event + "'; its events are "
                    + templates.keySet());
        }
        int wanted = template.attributeNames().size();
        if (values.length != wanted) {
            throw new IllegalArgumentException("task " + taskName + " raised '" + event + "' with " + values.length
                    + " values; the event has " + wanted + " attributes " + template.attributeNames());
        }
        return cell.raise(template, values);
    }

    void unbind() {
        if (cell.root().get(TASKS) instanceof DomainHandle d && d.get(taskName) == task.managed()) {
            d.remove(taskName);
        }
    }
}
