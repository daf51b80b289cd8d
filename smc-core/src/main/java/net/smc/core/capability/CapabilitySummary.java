package net.smc.core.capability;

import java.util.SortedSet;
import java.util.TreeSet;

/**
 * The compact capability description a discovery reply carries: the vehicle, its resources and the
 * names of its tasks. A commander decides from it whether to ask for the full description.
 */
public record CapabilitySummary(String vehicle, SortedSet<String> resources, SortedSet<String> tasks) {
    public CapabilitySummary {
        resources = java.util.Collections.unmodifiableSortedSet(new TreeSet<>(resources));
        tasks = java.util.Collections.unmodifiableSortedSet(new TreeSet<>(tasks));
    }

    /** Whether the vehicle has every resource and task the requirement names. */
    public boolean satisfies(CapabilityRequirement requirement) {
        return requirement.isMetBy(this);
    }

    /** Whether this summary is exactly the summary of {@code full}. */
    public boolean matches(CapabilityDescription full) {
        return equals(full.summary());
    }
}
