package net.smc.core.task;

import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.lang.reflect.Parameter;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import net.smc.policy.api.OpInterfaces;
import net.smc.core.capability.EventDescription;
import net.smc.core.capability.OperationDescription;
import net.smc.core.capability.TaskDescription;

/**
 * The reflective capability-description algorithm of the paper's Table V: describes one task from
 * the {@link TaskInterface} and {@link TaskEvent} annotations of the interfaces it implements.
 *
 * <pre>
 * FOR all interfaces implemented by the task
 *   IF it carries @TaskInterface
 *     IF the annotation names the task: each method is an event (@TaskEvent) or an operation
 *     ELSE error
 *   ELSE the interface contributes nothing
 * </pre>
 *
 * <p>How the pseudo code is read here, and why:
 * <ul>
 * <li>The task's name is its class's simple name ({@code Explorer}); by convention its interface
 *     is {@code ExplorerI}, but only the annotation's value is checked, as in Table V.</li>
 * <li>"Interfaces implemented by the task" are all the interfaces it is an instance of: those its
 *     class and superclasses declare, and their superinterfaces. So a subclass that is a task of
 *     its own ({@code FastExplorer extends Explorer}) fails: it implements {@code ExplorerI},
 *     which names another task.</li>
 * <li>Table V's "ELSE return empty description" is read per interface: an interface without
 *     {@code @TaskInterface} ({@code Runnable}, say) contributes nothing, so a task implementing
 *     {@code Runnable} and {@code ExplorerI} is described by {@code ExplorerI}. A task none of
 *     whose interfaces is annotated gets the empty description. Read literally, the first
 *     unannotated interface would empty the description of every task that also implements any
 *     ordinary interface, which cannot be what the paper's Explorer meant.</li>
 * <li>"All methods in the interface" are its public instance methods, inherited ones included
 *     (static methods are not part of what a task offers). Operations carry their argument types'
 *     simple names, events their attributes' names ({@link Attr}) and types' simple names.</li>
 * <li>The description is deterministic: operations sorted by name then argument types, events by
 *     name (reflection's method order is unspecified, and equal vehicles must describe equally).</li>
 * <li>Events become event templates named after them, so an event's name and attribute names must
 *     be PonderTalk identifiers, attribute names must be distinct, and two events of one task may
 *     not share a name with different attributes. Breaking these is an error too.</li>
 * </ul>
 */
public final class TaskDescriber {

    private TaskDescriber() {
    }

    /**
     * Describes a task class.
     *
     * @throws TaskDescriptionException when an interface names another task, or an event cannot
     *         become an event template; the message names the task, the interface or method and the rule
     */
    public static TaskDescription describe(Class<? extends Task> taskClass) throws TaskDescriptionException {
        String task = taskClass.getSimpleName();
        Set<OperationDescription> operations = new LinkedHashSet<>();
        TreeMap<String, EventDescription> events = new TreeMap<>();
        for (Class<?> iface : OpInterfaces.of(taskClass)) {
            TaskInterface marker = iface.getAnnotation(TaskInterface.class);
            if (marker == null) {
                continue;
            }
            if (!marker.value().equals(task)) {
                throw new TaskDescriptionException("task " + task + " implements " + iface.getSimpleName()
                        + ", whose @TaskInterface names '" + marker.value() + "'; a task interface must name the task"
                        + " that implements it ('" + task + "')");
            }
            for (Method m : iface.getMethods()) {
                if (Modifier.isStatic(m.getModifiers()) || m.isSynthetic()) {
                    continue;
                }
                if (m.isAnnotationPresent(TaskEvent.class)) {
                    addEvent(events, event(task, iface, m), task);
                } else {
                    operations.add(new OperationDescription(m.getName(), typeNames(m)));
                }
            }
        }
        List<OperationDescription> sorted = new ArrayList<>(operations);
        sorted.sort(Comparator.comparing(OperationDescription::name)
                .thenComparing(o -> String.join(",", o.argumentTypes())));
        return new TaskDescription(task, sorted, List.copyOf(events.values()));
    }

    private static List<String> typeNames(Method m) {
        List<String> names = new ArrayList<>();
        for (Class<?> p : m.getParameterTypes()) {
            names.add(p.getSimpleName());
        }
        return names;
    }

    private static EventDescription event(String task, Class<?> iface, Method m) throws TaskDescriptionException {
        String where = "event '" + m.getName() + "' of " + iface.getSimpleName() + " (task " + task + ")";
        if (!isIdentifier(m.getName())) {
            throw new TaskDescriptionException(where + ": its name is not a PonderTalk identifier"
                    + " (a letter, then letters, digits or _), so it cannot name an event template");
        }
        List<EventDescription.Attribute> attributes = new ArrayList<>();
        Set<String> seen = new TreeSet<>();
        Parameter[] params = m.getParameters();
        for (int i = 0; i < params.length; i++) {
            String name = attributeName(params[i], i, where);
            if (!seen.add(name)) {
                throw new TaskDescriptionException(where + ": attribute '" + name + "' appears twice;"
                        + " attribute names must be distinct");
            }
            attributes.add(new EventDescription.Attribute(name, params[i].getType().getSimpleName()));
        }
        return new EventDescription(m.getName(), attributes);
    }

    private static String attributeName(Parameter p, int index, String where) throws TaskDescriptionException {
        Attr attr = p.getAnnotation(Attr.class);
        String name;
        if (attr != null) {
            name = attr.value();
        } else if (p.isNamePresent()) {
            name = p.getName();
        } else {
            throw new TaskDescriptionException(where + ": parameter " + (index + 1) + " ("
                    + p.getType().getSimpleName() + ") has no attribute name; annotate it @Attr(\"name\")"
                    + " (class files keep parameter names only when compiled with -parameters)");
        }
        if (!isIdentifier(name)) {
            throw new TaskDescriptionException(where + ": attribute name '" + name + "' of parameter " + (index + 1)
                    + " is not a PonderTalk identifier (a letter, then letters, digits or _)");
        }
        return name;
    }

    private static void addEvent(TreeMap<String, EventDescription> events, EventDescription event, String task)
            throws TaskDescriptionException {
        EventDescription earlier = events.putIfAbsent(event.name(), event);
        if (earlier != null && !earlier.equals(event)) {
            throw new TaskDescriptionException("task " + task + " has two events named '" + event.name()
                    + "' with different attributes (" + attributes(earlier) + " and " + attributes(event)
                    + "); an event's name must identify one event template");
        }
    }

    /** {@code [x double, y double]}, for messages. */
    private static String attributes(EventDescription event) {
        return event.attributes().stream().map(a -> a.name() + " " + a.type()).toList().toString();
    }

    /** A PonderTalk identifier: an ASCII letter, then ASCII letters, digits or {@code _}. */
    static boolean isIdentifier(String s) {
        if (s.isEmpty() || !isLetter(s.charAt(0))) {
            return false;
        }
        for (int i = 1; i < s.length(); i++) {
            char c = s.charAt(i);
            if (!isLetter(c) && !(c >= '0' && c <= '9') && c != '_') {
                return false;
            }
        }
        return true;
    }

    private static boolean isLetter(char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
    }
}
