package net.smc.core.capability;

import java.util.List;
import java.util.Set;
import java.util.SortedSet;
import java.util.TreeSet;

/**
 * What one vehicle can do: the union of its loaded tasks' descriptions plus its resources (sensors
 * and devices such as {@code motion}, {@code video}, {@code infrared}, {@code chemical},
 * {@code communication}). The full form is what a full capability request returns; its
 * {@link #summary()} is what a discovery reply carries.
 */
public record CapabilityDescription(String vehicle, SortedSet<String> resources, List<TaskDescription> tasks) {
    public CapabilityDescription {
        resources = java.util.Collections.unmodifiableSortedSet(new TreeSet<>(resources));
        tasks = List.copyOf(tasks);
    }

    public static CapabilityDescription of(String vehicle, Set<String> resources, List<TaskDescription> tasks) {
        return new CapabilityDescription(vehicle, new TreeSet<>(resources), tasks);
    }

    /** The names of the tasks, sorted. */
    public SortedSet<String> taskNames() {
        TreeSet<String> names = new TreeSet<>();
        tasks.forEach(t -> names.add(t.task()));
        return java.util.Collections.unmodifiableSortedSet(names);
    }

    /** Whether the vehicle has every resource and task the requirement names. */
    public boolean satisfies(CapabilityRequirement requirement) {
        return requirement.isMetBy(this);
    }

    /** Whether the vehicle has a task of that name: {@code taskNames().contains(name)} without building the set. */
    public boolean hasTask(String name) {
        for (TaskDescription t : tasks) {
            if (t.task().equals(name)) {
                return true;
            }
        }
        return false;
    }

        /** The description of the named task, if the vehicle has it. */
    public java.util.Optional<TaskDescription> task(String name) {
        return tasks.stream().filter(t -> t.task().equals(name)).findFirst();
    }

    /** The compact form a discovery reply carries. */
    public CapabilitySummary summary() {
        return new CapabilitySummary(vehicle, resources, taskNames());
    }
}
