package net.smc.core.role;

import java.util.List;

/**
 * What one {@link RoleManager#load} added to the cell: the policy files it ran (by label), the
 * names of the new obligation policies (under {@code root/role/<role>/policy}), authorisation
 * policies ({@code .../auth}) and tasks ({@code .../task}). All empty when the role was already
 * present.
 */
public record Loaded(String role, List<String> sources, List<String> policies, List<String> authorisations,
                     List<String> tasks) {
    public Loaded {
        sources = List.copyOf(sources);
        policies = List.copyOf(policies);
        authorisations = List.copyOf(authorisations);
        tasks = List.copyOf(tasks);
    }

    /** Whether the load changed nothing because every file and task of the role was already present. */
    public boolean alreadyPresent() {
        return sources.isEmpty() && tasks.isEmpty();
    }
}
