package net.smc.sim.task;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Objects;
import java.util.SortedSet;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.function.Function;
import net.smc.core.capability.TaskDescription;
import net.smc.core.task.Task;
import net.smc.core.task.TaskDescriber;
import net.smc.core.task.TaskDescriptionException;

/**
 * The tasks a robot can be given, by name: their classes, their capability descriptions (the
 * paper's Table V, by the reflective {@link TaskDescriber}) and how to make one for a robot. The
 * name is the class's simple name (the paper's naming scheme), checked when a task is added.
 *
 * <pre>{@code
 * TaskCatalog catalog = TaskCatalog.standard();
 * catalog.describe("Explorer");                  // operations explore, halt ...; events obstacle, areaExplored ...
 * Task t = catalog.create("Explorer", context);  // a new Explorer on that robot
 * }</pre>
 */
public final class TaskCatalog {
    private final TreeMap<String, Entry> entries;

    private record Entry(Class<? extends Task> type, TaskDescription description, Function<TaskContext, ? extends Task> factory) {
    }

    private TaskCatalog(TreeMap<String, Entry> entries) {
        this.entries = entries;
    }

    /** The tasks of this package: Explorer, Navigator, HazardDetector, Aggregator, Relay, Beacon, Assist. */
    public static TaskCatalog standard() {
        return builder()
                .add(Explorer.class, Explorer::new)
                .add(Navigator.class, Navigator::new)
                .add(HazardDetector.class, HazardDetector::new)
                .add(Aggregator.class, Aggregator::new)
                .add(Relay.class, Relay::new)
                .add(Beacon.class, Beacon::new)
                .add(Assist.class, Assist::new)
                .build();
    }

    public static Builder builder() {
        return new Builder();
    }

    /** The names of the tasks, sorted. */
    public SortedSet<String> names() {
        return Collections.unmodifiableSortedSet(new TreeSet<>(entries.keySet()));
    }

    public boolean contains(String name) {
        return entries.containsKey(name);
    }

    /**
     * The class of a task.
     *
     * @throws IllegalArgumentException naming the known tasks, when there is no such task
     */
    public Class<? extends Task> type(String name) {
        return entry(name).type();
    }

    /** The capability description of a task (Table V). */
    public TaskDescription describe(String name) {
        return entry(name).description();
    }

    /** A new instance of a task on the robot of {@code context}. */
    public Task create(String name, TaskContext context) {
        Objects.requireNonNull(context, "context");
        Task task = entry(name).factory().apply(context);
        if (task == null || task.getClass() != entry(name).type()) {
            throw new IllegalStateException("the factory of task '" + name + "' made "
                    + (task == null ? "nothing" : "a " + task.getClass().getName()) + ", not a " + entry(name).type().getName());
        }
        return task;
    }

    private Entry entry(String name) {
        Entry e = entries.get(name);
        if (e == null) {
            throw new IllegalArgumentException("unknown task '" + name + "'; the known tasks are "
                    + String.join(", ", entries.keySet()));
        }
        return e;
    }

    /** Collects tasks; each is described when added. */
    public static final class Builder {
        private final Map<String, Entry> entries = new LinkedHashMap<>();

        private Builder() {
        }

        /**
         * Adds a task class with its factory.
         *
         * @throws IllegalArgumentException when the class cannot be described (the describer's reason),
         *                                  or a task of its name is already in the catalogue
         */
        public <T extends Task> Builder add(Class<T> type, Function<TaskContext, T> factory) {
            Objects.requireNonNull(type, "type");
            Objects.requireNonNull(factory, "factory of task " + type.getSimpleName());
            TaskDescription description;
            try {
                description = TaskDescriber.describe(type);
            } catch (TaskDescriptionException e) {
                throw new IllegalArgumentException("task class " + type.getName() + " cannot join the catalogue: "
                        + e.getMessage(), e);
            }
            if (entries.containsKey(description.task())) {
                throw new IllegalArgumentException("the catalogue already has a task named '" + description.task()
                        + "' (" + entries.get(description.task()).type().getName() + "); task names must be unique");
            }
            entries.put(description.task(), new Entry(type, description, factory));
            return this;
        }

        public TaskCatalog build() {
            return new TaskCatalog(new TreeMap<>(entries));
        }
    }
}
