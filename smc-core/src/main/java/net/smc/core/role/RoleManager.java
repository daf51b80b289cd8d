package net.smc.core.role;

import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.Set;
import net.smc.core.task.Task;
import net.smc.policy.PolicyEngine;
import net.smc.policy.api.DomainHandle;
import net.smc.policy.api.Handle;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The Role-Manager of one cell (the paper's section IV-A): loads a role onto the cell when the
 * vehicle is assigned to it, and withdraws it at reconfiguration. A loaded role is the domain
 * {@code root/role/<name>} with its obligation policies in {@code policy}, its authorisation
 * policies in {@code auth}, its tasks in {@code task} and the subjects standing for collaborating
 * roles' cells in {@code peers}.
 *
 * <ul>
 *   <li>A load is all or nothing: if a policy file fails (syntax error, runtime error, an error
 *       reported while it ran, a missing URI, a broken convention) or a task cannot be made or
 *       started, the cell is left exactly as it was and {@link RoleLoadException} names the part
 *       and the reasons.</li>
 *   <li>A load is idempotent: files and tasks already present for the role are not loaded again
 *       (the paper: "unless already present").</li>
 *   <li>A withdrawal leaves nothing of the role: its policies are deactivated and detached, its
 *       tasks stopped and taken out of {@code root/task}, the entries its files and tasks added
 *       elsewhere removed, its domain removed (and {@code root/role}, if this manager made it and it
 *       is now empty).</li>
 * </ul>
 *
 * <pre>{@code
 * RoleManager roles = RoleManager.builder(cell).reassignment(teamProtocols::reassign).build();
 * roles.load(Role.builder("surveyor").mission("policy:/roles/surveyor/mission")
 *         .authorisation("policy:/roles/surveyor/auth").manages("hdetector", "relay").build());
 * roles.withdraw("surveyor");
 * }</pre>
 *
 * Runs on the cell's thread, like the cell; not thread-safe.
 */
public final class RoleManager {
    /** The name of the domain under root that holds the roles. */
    public static final String ROLE_DOMAIN = "role";

    private static final Logger LOG = LoggerFactory.getLogger(RoleManager.class);

    private final PolicyEngine cell;
    private final Reassignment reassignment;
    private final Map<String, LoadedRole> roles = new LinkedHashMap<>();
    private boolean loading;
    private boolean madeRoleDomain;

    private RoleManager(Builder builder) {
        this.cell = builder.cell;
        this.reassignment = builder.reassignment;
    }

    public static Builder builder(PolicyEngine cell) {
        return new Builder(cell);
    }

    /** Settings of a Role-Manager. */
    public static final class Builder {
        private final PolicyEngine cell;
        private Reassignment reassignment = Reassignment.NONE;

        private Builder(PolicyEngine cell) {
            this.cell = Objects.requireNonNull(cell, "cell");
        }

        /** Who carries out {@code reassign:scheme:} (default: {@link Reassignment#NONE}, which refuses). */
        public Builder reassignment(Reassignment service) {
            this.reassignment = Objects.requireNonNull(service, "reassignment");
            return this;
        }

        public RoleManager build() {
            return new RoleManager(this);
        }
    }

    /**
     * Loads a role, or the parts of it not yet present.
     *
     * @return what was added (nothing, when the role was already complete)
     * @throws RoleLoadException when any part fails; the cell is then as it was
     * @throws IllegalStateException when called while another load runs (from a task started by it, say)
     */
    public Loaded load(Role role) throws RoleLoadException {
        Objects.requireNonNull(role, "role");
        if (loading) {
            throw new IllegalStateException("role '" + role.name() + "' cannot be loaded while another role is loading");
        }
        LoadTransaction load = new LoadTransaction(cell, role, roles.get(role.name()), reassignment);
        if (load.nothingToDo()) {
            LOG.debug("role '{}' is already loaded", role.name());
            return new Loaded(role.name(), List.of(), List.of(), List.of(), List.of());
        }
        loading = true;
        try {
            roles.put(role.name(), load.run());
            madeRoleDomain |= load.createdRoleDomain();
        } finally {
            loading = false;
        }
        Loaded loaded = load.report();
        LOG.debug("loaded {}", loaded);
        return loaded;
    }

    /**
     * Withdraws a role: stops its tasks, deactivates and detaches its policies, removes what its
     * files added outside its domain, and removes its domain. Completes even if a task fails to
     * stop, and then reports it.
     *
     * @throws IllegalArgumentException when the role is not loaded here
     * @throws IllegalStateException    after the withdrawal, when tasks failed to stop
     */
    public void withdraw(String name) {
        LoadedRole role = roles.get(name);
        if (role == null) {
            throw new IllegalArgumentException("role '" + name + "' is not loaded on this cell (loaded: " + loadedRoles() + ")");
        }
        List<String> problems = new ArrayList<>();
        for (Map.Entry<String, Task> task : role.tasks.entrySet()) {
            try {
                task.getValue().stop();
            } catch (RuntimeException e) {
                problems.add("task '" + task.getKey() + "' failed to stop: " + e);
            }
        }
        for (Task task : role.bound) {
            task.unbind();
        }
        for (Handle policy : Policies.under(role.object.domain())) {
            Policies.retire(policy);
        }
        for (TreeSnapshot.Addition addition : role.outside) {
            addition.undo();
        }
        for (TreeSnapshot.Addition made : role.madeDomains) {
            if (made.value() instanceof DomainHandle d && d.entries().isEmpty()) {
                made.undo();
            }
        }
        if (cell.root().get(ROLE_DOMAIN) instanceof DomainHandle holder) {
            if (holder.get(name) == role.object.domain()) {
                holder.remove(name);
            }
            if (madeRoleDomain && holder.entries().isEmpty()) {
                cell.root().remove(ROLE_DOMAIN);
                madeRoleDomain = false;
            }
        }
        // Emptying the role's domains also drops the parent links they gave to objects outside it.
        for (Handle node : Policies.reachable(role.object.domain())) {
            if (node instanceof DomainHandle d) {
                d.removeAll();
            }
        }
        roles.remove(name);
        LOG.debug("withdrew role '{}'", name);
        if (!problems.isEmpty()) {
            throw new IllegalStateException("role '" + name + "' was withdrawn, but " + String.join("; ", problems));
        }
    }

    public boolean isLoaded(String name) {
        return roles.containsKey(name);
    }

    /** The names of the loaded roles, in load order. */
    public Set<String> loadedRoles() {
        return Collections.unmodifiableSet(new LinkedHashSet<>(roles.keySet()));
    }

    /** The description a loaded role was last loaded with. */
    public Optional<Role> role(String name) {
        LoadedRole role = roles.get(name);
        return role == null ? Optional.empty() : Optional.of(role.object.role());
    }

    PolicyEngine cell() {
        return cell;
    }

    /** The role object of a loaded role, or {@code null}. */
    RoleObject roleObject(String name) {
        LoadedRole role = roles.get(name);
        return role == null ? null : role.object;
    }
}
