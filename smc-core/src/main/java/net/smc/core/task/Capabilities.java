package net.smc.core.task;

import net.smc.core.capability.TaskDescription;
import net.smc.core.capability.CapabilitySummary;
import net.smc.core.capability.CapabilityRequirement;
import net.smc.core.capability.CapabilityDescription;
import net.smc.core.capability.CapabilityCodec;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.Set;
import java.util.SortedSet;
import java.util.TreeMap;
import java.util.TreeSet;
import net.smc.core.task.Task;
import net.smc.core.task.TaskDescriptionException;

/**
 * The Capability module of one vehicle (the paper's section IV-B): its resources (sensors and
 * devices) and the tasks loaded in it, from which it prepares the vehicle's capability description
 * on request. The description is never stored: it is built from the loaded tasks each time, so it
 * changes as soon as a task is loaded or unloaded.
 *
 * <p>Loading describes the task once (Table V, {@link Task#describe()}) and refuses a task that
 * cannot be described, so a vehicle never advertises a capability it cannot honour. Loading only
 * registers the task: starting it and binding it to the cell is the Role-Manager's business.
 * Not thread-safe: use it from the cell's thread.
 *
 * <pre>{@code
 * Capabilities caps = new Capabilities("uav7", Set.of("motion", "video"));
 * caps.load(new Explorer());
 * byte[] reply = CapabilityCodec.STANDARD.encode(caps.summary());   // a discovery reply's payload
 * }</pre>
 */
public final class Capabilities {
    private final String vehicle;
    private final TreeSet<String> resources = new TreeSet<>();
    private final TreeMap<String, Loaded> tasks = new TreeMap<>();

    private record Loaded(Task task, TaskDescription description) {
    }

    public Capabilities(String vehicle, Set<String> resources) {
        this.vehicle = Objects.requireNonNull(vehicle, "vehicle");
        resources.forEach(this::addResource);
    }

    public String vehicle() {
        return vehicle;
    }

    /** The resources, sorted (a read-only copy). */
    public SortedSet<String> resources() {
        return Collections.unmodifiableSortedSet(new TreeSet<>(resources));
    }

    /** Adds a resource (a sensor came up); answers whether it was new. */
    public boolean addResource(String resource) {
        if (Objects.requireNonNull(resource, "resource").isBlank()) {
            throw new IllegalArgumentException("a resource name must not be blank");
        }
        return resources.add(resource);
    }

    /** Removes a resource (a sensor failed); answers whether it was there. */
    public boolean removeResource(String resource) {
        return resources.remove(resource);
    }

    /**
     * Loads a task: from now on the description includes it. Loading the same task again does
     * nothing.
     *
     * @return the task's description
     * @throws TaskDescriptionException when the task cannot be described (it is not loaded)
     * @throws IllegalStateException    when another task of the same name is loaded
     */
    public TaskDescription load(Task task) throws TaskDescriptionException {
        TaskDescription description = task.describe();
        Loaded earlier = tasks.get(description.task());
        if (earlier != null && earlier.task() != task) {
            throw new IllegalStateException("vehicle " + vehicle + " already has a task named '" + description.task()
                    + "'; unload it first (a vehicle has one task per name)");
        }
        tasks.put(description.task(), new Loaded(task, description));
        return description;
    }

    /** Unloads the task of that name; answers it, or nothing if no such task was loaded. */
    public Optional<Task> unload(String taskName) {
        Loaded removed = tasks.remove(taskName);
        return removed == null ? Optional.empty() : Optional.of(removed.task());
    }

    public Optional<Task> task(String taskName) {
        Loaded loaded = tasks.get(taskName);
        return loaded == null ? Optional.empty() : Optional.of(loaded.task());
    }

    /** The loaded tasks, by name. */
    public List<Task> tasks() {
        List<Task> all = new ArrayList<>();
        for (Map.Entry<String, Loaded> e : tasks.entrySet()) {
            all.add(e.getValue().task());
        }
        return all;
    }

    /** The full description, tasks sorted by name: what a full capability request returns. */
    public CapabilityDescription description() {
        List<TaskDescription> described = tasks.values().stream().map(Loaded::description).toList();
        return CapabilityDescription.of(vehicle, resources, described);
    }

    /** The compact form: what a discovery reply carries. */
    public CapabilitySummary summary() {
        return new CapabilitySummary(vehicle, resources, tasks.navigableKeySet());
    }

    public boolean satisfies(CapabilityRequirement requirement) {
        return requirement.isMetBy(summary());
    }
}
