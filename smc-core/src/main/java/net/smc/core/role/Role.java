package net.smc.core.role;

import java.util.ArrayList;
import java.util.Collection;
import java.util.Collections;
import java.util.HashSet;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.function.Supplier;
import net.smc.core.task.Task;

/**
 * A role (the paper's section II-B.2): the placeholder a vehicle is assigned to, made of its
 * role-mission (obligation policies), its authorisations (authorisation policies) and its tasks,
 * with an external and a local interface. This is the immutable description that mission
 * specifications produce and role-assignment messages carry; {@link RoleManager} loads it onto a
 * cell, where it becomes the domain {@code root/role/<name>}.
 *
 * <pre>{@code
 * Role surveyor = Role.builder("surveyor")
 *         .mission("policy:/roles/surveyor/mission")
 *         .authorisation("policy:/roles/surveyor/auth")
 *         .task("Explorer", Explorer::new)
 *         .manages("hdetector", "relay")
 *         .build();
 * }</pre>
 *
 * @param name           the role's name, also its domain's ({@code root/role/surveyor})
 * @param mission        files that create the role-mission's obligation policies
 * @param authorisations files that create the role's authorisation policies
 * @param tasks          the role's tasks, started when it is loaded and stopped when it is withdrawn
 * @param manages        the roles this role manages in the management tree (the mission class's
 *                       {@code roleManagement}); it may re-assign only these
 * @param external       the external interface
 * @param local          the local interface
 */
public record Role(String name, List<PolicySource> mission, List<PolicySource> authorisations, List<TaskBinding> tasks,
                   Set<String> manages, ExternalInterface external, LocalInterface local) {

    public Role {
        RoleNames.checkRole("role name", name);
        mission = List.copyOf(mission);
        authorisations = List.copyOf(authorisations);
        tasks = List.copyOf(tasks);
        manages = Collections.unmodifiableSortedSet(new TreeSet<>(manages));
        external = external == null ? ExternalInterface.NONE : external;
        local = local == null ? LocalInterface.NONE : local;
        checkLabelsUnique(name, mission, authorisations);
        Set<String> taskNames = checkTasksUnique(name, tasks);
        for (String managed : manages) {
            RoleNames.checkRole("role managed by '" + name + "'", managed);
            if (managed.equals(name)) {
                throw new IllegalArgumentException("role '" + name + "' cannot manage itself");
            }
        }
        checkInterfaces(name, taskNames, external, local);
    }

    public static Builder builder(String name) {
        return new Builder(name);
    }

    /** Every policy source of the role, role-mission first. */
    public List<PolicySource> policySources() {
        List<PolicySource> all = new ArrayList<>(mission);
        all.addAll(authorisations);
        return all;
    }

    /**
     * The operations this role requires that no role of {@code team} (by name) exports, each as a
     * sentence; empty when every requirement is met. For mission loaders, before assigning anyone.
     */
    public List<String> unmetRequirements(Map<String, Role> team) {
        List<String> unmet = new ArrayList<>();
        for (RequiredOperation required : external.requiredOperations()) {
            Role provider = team.get(required.role());
            if (provider == null) {
                unmet.add("role '" + name + "' requires '" + required.selector() + "' of role '" + required.role()
                        + "', which is not in the team");
            } else if (provider.external().exportedOperation(required.selector()) == null) {
                unmet.add("role '" + name + "' requires '" + required.selector() + "' of role '" + required.role()
                        + "', which does not export it");
            }
        }
        return unmet;
    }

    private static void checkLabelsUnique(String role, List<PolicySource> mission, List<PolicySource> authorisations) {
        Set<String> labels = new HashSet<>();
        for (PolicySource source : concat(mission, authorisations)) {
            if (!labels.add(source.label())) {
                throw new IllegalArgumentException("policy '" + source.label() + "' is listed twice in role '" + role
                        + "'; each policy file is loaded once per role");
            }
        }
    }

    private static Set<String> checkTasksUnique(String role, List<TaskBinding> tasks) {
        Set<String> names = new HashSet<>();
        for (TaskBinding task : tasks) {
            if (!names.add(task.name())) {
                throw new IllegalArgumentException("task '" + task.name() + "' is listed twice in role '" + role + "'");
            }
        }
        return names;
    }

    private static void checkInterfaces(String role, Set<String> tasks, ExternalInterface external, LocalInterface local) {
        for (TaskOperation op : local.operations()) {
            if (!tasks.contains(op.task())) {
                throw new IllegalArgumentException("local operation '" + op.selector() + "' of role '" + role
                        + "' names task '" + op.task() + "', which is not one of the role's tasks " + tasks);
            }
        }
        for (TaskOperation op : external.exported()) {
            if (!local.operations().contains(op)) {
                throw new IllegalArgumentException("exported operation '" + op.selector() + "' of task '" + op.task()
                        + "' is not in the local interface of role '" + role + "'; a role exports only its tasks' operations");
            }
        }
        for (String event : external.published()) {
            if (!local.events().contains(event)) {
                throw new IllegalArgumentException("published event '" + event + "' is not in the local interface of role '"
                        + role + "'; a role publishes only events raised inside it");
            }
        }
    }

    private static List<PolicySource> concat(Collection<PolicySource> a, Collection<PolicySource> b) {
        List<PolicySource> all = new ArrayList<>(a);
        all.addAll(b);
        return all;
    }

    /** Collects a role's parts; {@link #build()} checks them. */
    public static final class Builder {
        private final String name;
        private final List<PolicySource> mission = new ArrayList<>();
        private final List<PolicySource> authorisations = new ArrayList<>();
        private final List<TaskBinding> tasks = new ArrayList<>();
        private final Set<String> manages = new LinkedHashSet<>();
        private ExternalInterface external = ExternalInterface.NONE;
        private LocalInterface local = LocalInterface.NONE;

        private Builder(String name) {
            this.name = name;
        }

        /** Adds role-mission files by URI. */
        public Builder mission(String... uris) {
            for (String uri : uris) {
                mission.add(PolicySource.uri(uri));
            }
            return this;
        }

        public Builder mission(PolicySource source) {
            mission.add(source);
            return this;
        }

        /** Adds authorisation files by URI. */
        public Builder authorisation(String... uris) {
            for (String uri : uris) {
                authorisations.add(PolicySource.uri(uri));
            }
            return this;
        }

        public Builder authorisation(PolicySource source) {
            authorisations.add(source);
            return this;
        }

        public Builder task(String taskName, Supplier<? extends Task> factory) {
            tasks.add(new TaskBinding(taskName, factory));
            return this;
        }

        public Builder manages(String... roles) {
            manages.addAll(List.of(roles));
            return this;
        }

        public Builder external(ExternalInterface anInterface) {
            this.external = anInterface;
            return this;
        }

        public Builder local(LocalInterface anInterface) {
            this.local = anInterface;
            return this;
        }

        public Role build() {
            return new Role(name, mission, authorisations, tasks, manages, external, local);
        }
    }
}
