package net.smc.core.capability;

import java.util.Collections;
import java.util.Set;
import java.util.SortedSet;
import java.util.TreeSet;

/**
 * What a role needs from a vehicle: resources (sensors and devices, {@code "video"}) and tasks, by
 * task name ({@code "Explorer"}, whose interface is {@code ExplorerI}). Role matching checks it
 * against a discovery reply's summary first and the full description after (the paper's
 * Algorithm 2); both answer the same here, since both carry the task names, so a summary that
 * {@link CapabilitySummary#matches matches} its full form never passes one check and fails the other.
 *
 * <pre>{@code
 * CapabilityRequirement surveyor = CapabilityRequirement.of(Set.of("motion", "video"), Set.of("Explorer"));
 * if (!surveyor.isMetBy(summary)) log.debug("not a surveyor: lacks {}", surveyor.missingFrom(summary).describe());
 * }</pre>
 *
 * @param resources the resource names needed (copied, sorted)
 * @param tasks     the task names needed (copied, sorted)
 */
public record CapabilityRequirement(Set<String> resources, Set<String> tasks) {
    private static final CapabilityRequirement NONE = new CapabilityRequirement(Set.of(), Set.of());

    public CapabilityRequirement {
        resources = Collections.unmodifiableSortedSet(new TreeSet<>(resources));
        tasks = Collections.unmodifiableSortedSet(new TreeSet<>(tasks));
    }

    public static CapabilityRequirement of(Set<String> resources, Set<String> tasks) {
        return new CapabilityRequirement(resources, tasks);
    }

    /** The requirement that every vehicle meets. */
    public static CapabilityRequirement none() {
        return NONE;
    }

    public boolean isEmpty() {
        return resources.isEmpty() && tasks.isEmpty();
    }

    public boolean isMetBy(CapabilitySummary summary) {
        return summary.resources().containsAll(resources) && summary.tasks().containsAll(tasks);
    }

    public boolean isMetBy(CapabilityDescription description) {
        if (!description.resources().containsAll(resources)) {
            return false;
        }
        for (String task : tasks) {
            if (!description.hasTask(task)) {
                return false;
            }
        }
        return true;
    }

    /** The part of this requirement the vehicle lacks; empty when it is met. */
    public CapabilityRequirement missingFrom(CapabilitySummary summary) {
        SortedSet<String> lackedResources = new TreeSet<>(resources);
        lackedResources.removeAll(summary.resources());
        SortedSet<String> lackedTasks = new TreeSet<>(tasks);
        lackedTasks.removeAll(summary.tasks());
        return new CapabilityRequirement(lackedResources, lackedTasks);
    }

    public CapabilityRequirement missingFrom(CapabilityDescription description) {
        return missingFrom(description.summary());
    }

    /** For messages: {@code resources [video, infrared] and tasks [Explorer]}, or {@code nothing}. */
    public String describe() {
        if (isEmpty()) {
            return "nothing";
        }
        if (tasks.isEmpty()) {
            return "resources " + resources;
        }
        if (resources.isEmpty()) {
            return "tasks " + tasks;
        }
        return "resources " + resources + " and tasks " + tasks;
    }
}
