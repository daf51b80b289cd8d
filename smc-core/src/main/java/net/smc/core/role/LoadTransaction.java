package net.smc.core.role;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import net.smc.core.task.Task;
import net.smc.core.task.TaskDescriptionException;
import net.smc.policy.PolicyEngine;
import net.smc.policy.api.Diagnostic;
import net.smc.policy.RunResult;
import net.smc.policy.api.PolicyHandle;
import net.smc.policy.api.DomainHandle;
import net.smc.policy.api.OpInterfaces;
import net.smc.policy.api.Handle;

/**
 * One load of a role, all or nothing. In order: bind the missing tasks under
 * {@code root/role/<name>/task} and, for a task listed under its own name ({@link Task#name()}) and
 * not yet bound, at {@code root/task/<name>} with its event templates ({@link Task#bind}), check the local interface against them, run the missing policy
 * files (role-mission, then authorisations) checking each against the convention of
 * {@code policies/README.md}, activate the new authorisation and then obligation policies, start
 * the new tasks. If anything fails, every policy the load created is deactivated and detached, the
 * tasks it started are stopped, and the domain tree is put back exactly as it was.
 */
final class LoadTransaction {
    private final PolicyEngine cell;
    private final DomainHandle root;
    private final Role role;
    private final LoadedRole existing;
    private final Reassignment reassignment;

    private final List<Handle> created = new ArrayList<>();
    private final List<Task> started = new ArrayList<>();
    private final List<String> sourcesRun = new ArrayList<>();
    private final List<String> newPolicies = new ArrayList<>();
    private final List<String> newAuthorisations = new ArrayList<>();
    private final Map<String, Task> newTasks = new LinkedHashMap<>();
    private final List<TreeSnapshot.Addition> outside = new ArrayList<>();
    private final List<Task> bound = new ArrayList<>();
    private final List<TreeSnapshot.Addition> madeDomains = new ArrayList<>();
    private boolean createdRoleDomain;

    LoadTransaction(PolicyEngine cell, Role role, LoadedRole existing, Reassignment reassignment) {
        this.cell = cell;
        this.root = cell.root();
        this.role = role;
        this.existing = existing;
        this.reassignment = reassignment;
    }

    /** Whether the role and every file and task of it are already on the cell. */
    boolean nothingToDo() {
        return existing != null && missingSources().isEmpty() && missingTasks().isEmpty();
    }

    boolean createdRoleDomain() {
        return createdRoleDomain;
    }

    /**
     * Runs the load.
     *
     * @return the record of the loaded role (the existing one, extended, on a second load)
     * @throws RoleLoadException with the cell as it was before
     */
    LoadedRole run() throws RoleLoadException {
        TreeSnapshot base = TreeSnapshot.of(root);
        PolicyFactoryTap.Installed tap = PolicyFactoryTap.install(cell);
        RoleObject object = null;
        try {
            object = roleObject();
            bindTasks(object);
            checkLocalInterface(object);
            for (PolicySource source : missingSources()) {
                runSource(source, object, tap);
            }
            tap.close();
            activate(object);
            startTasks();
        } catch (RoleLoadException e) {
            tap.close();
            rollBack(base);
            throw e;
        } catch (RuntimeException e) {
            tap.close();
            rollBack(base);
            throw new RoleLoadException(role.name(), "the Role-Manager", List.of(e.toString()));
        }
        return commit(object);
    }

    Loaded report() {
        return new Loaded(role.name(), sourcesRun, newPolicies, newAuthorisations, List.copyOf(newTasks.keySet()));
    }

    private List<PolicySource> missingSources() {
        return role.policySources().stream()
                .filter(s -> existing == null || !existing.sources.contains(s.label()))
                .toList();
    }

    private List<TaskBinding> missingTasks() {
        return role.tasks().stream().filter(t -> existing == null || !existing.tasks.containsKey(t.name())).toList();
    }

    private RoleObject roleObject() throws RoleLoadException {
        if (existing != null) {
            return existing.object;
        }
        Object holder = root.get(RoleManager.ROLE_DOMAIN);
        DomainHandle roles;
        if (holder == null) {
            roles = cell.newDomain();
            root.put(RoleManager.ROLE_DOMAIN, roles);
            createdRoleDomain = true;
        } else if (holder instanceof DomainHandle d) {
            roles = d;
        } else {
            throw fail("the role domain", "root/" + RoleManager.ROLE_DOMAIN + " is a " + PolicyEngine.className(holder)
                    + "; the Role-Manager keeps roles in a domain there");
        }
        if (roles.get(role.name()) != null) {
            throw fail("the role domain", "root/role/" + role.name() + " is already taken by "
                    + PolicyEngine.print(roles.get(role.name())) + ", which this Role-Manager did not load");
        }
        RoleObject object = new RoleObject(cell, role, reassignment);
        roles.put(role.name(), object.domain());
        return object;
    }

    private void bindTasks(RoleObject object) throws RoleLoadException {
        DomainHandle taskDomain = object.part(RoleObject.TASK);
        TreeSnapshot before = TreeSnapshot.of(root);
        for (TaskBinding binding : missingTasks()) {
            Task task;
            Handle handle;
            try {
                task = binding.factory().get();
                if (task == null) {
                    throw new IllegalStateException("its factory answered null");
                }
                handle = task.managed();
            } catch (RuntimeException e) {
                throw fail("task '" + binding.name() + "'", "it could not be made: " + e.getMessage());
            }
            if (taskDomain.get(binding.name()) != null) {
                throw fail("task '" + binding.name() + "'", "root/role/" + role.name() + "/task/" + binding.name()
                        + " is already taken");
            }
            taskDomain.put(binding.name(), handle);
            newTasks.put(binding.name(), task);
            if (binding.name().equals(task.name()) && !task.isBound()) {
                try {
                    task.bind(cell);
                } catch (TaskDescriptionException | RuntimeException e) {
                    throw fail("task '" + binding.name() + "'", "it could not be bound at root/task: " + e.getMessage());
                }
                bound.add(task);
            }
        }
        // What binding added outside the role (root/task/<name>, event templates) goes with the role.
        TreeSnapshot after = TreeSnapshot.of(root);
        // A root/task or root/event domain made here goes only once empty: other roles' tasks may share it.
        for (TreeSnapshot.Addition a : before.changesTo(after, after.below(object.domain()), root).added()) {
            (a.value() instanceof DomainHandle ? madeDomains : outside).add(a);
        }
    }

    private void checkLocalInterface(RoleObject object) throws RoleLoadException {
        DomainHandle taskDomain = object.part(RoleObject.TASK);
        for (TaskOperation op : role.local().operations()) {
            Object handle = taskDomain.get(op.task());
            Handle type = handle instanceof Handle m ? m : null;
            if (type == null || !type.selectors().contains(op.selector())) {
                throw fail("the local interface", "task '" + op.task() + "' ("
                        + (type == null ? "missing" : type.className()) + ") has no operation '" + op.selector() + "'");
            }
        }
    }

    private void runSource(PolicySource source, RoleObject object, PolicyFactoryTap.Installed tap) throws RoleLoadException {
        String part = "policy '" + source.label() + "'";
        TreeSnapshot before = TreeSnapshot.of(root);
        RunResult result = source.runIn(cell);
        List<Handle> made = tap.drain();
        created.addAll(made);
        if (!result.ok() || !result.diagnostics().isEmpty()) {
            throw new RoleLoadException(role.name(), part, reasons(result));
        }
        TreeSnapshot after = TreeSnapshot.of(root);
        TreeSnapshot.Changes changes = before.changesTo(after, after.below(object.domain()), root);
        if (!changes.changed().isEmpty()) {
            throw fail(part, "it " + String.join(", ", changes.changed()) + "; a role's files may add entries"
                    + " but must not replace or remove existing ones");
        }
        checkOwnPart(part, object, RoleObject.POLICY, true, before, newPolicies);
        checkOwnPart(part, object, RoleObject.AUTH, false, before, newAuthorisations);
        for (Handle policy : made) {
            boolean obligation = policy instanceof PolicyHandle p && p.isObligation();
            String wanted = obligation ? RoleObject.POLICY : RoleObject.AUTH;
            if (!object.part(wanted).hasObject(policy)) {
                throw fail(part, "it created " + (obligation ? "an obligation" : "an authorisation")
                        + " policy that it did not store under root/role/" + role.name() + "/" + wanted
                        + " (the convention of policies/README.md)");
            }
        }
        outside.addAll(changes.added());
        sourcesRun.add(source.label());
    }

    /** New entries of the role's policy or auth domain must be policies of the right kind. */
    private void checkOwnPart(String part, RoleObject object, String name, boolean obligations, TreeSnapshot before,
                              List<String> added) throws RoleLoadException {
        DomainHandle domain = object.part(name);
        Map<String, Object> earlier = before.entriesOf(domain);
        for (Map.Entry<String, Object> e : domain.entries().entrySet()) {
            if (earlier.containsKey(e.getKey())) {
                continue;
            }
            if (!(e.getValue() instanceof PolicyHandle p && p.isObligation() == obligations)) {
                throw fail(part, "root/role/" + role.name() + "/" + name + "/" + e.getKey() + " is a "
                        + PolicyEngine.className(e.getValue()) + "; root/role/" + role.name() + "/" + name + " holds only "
                        + (obligations ? "obligation" : "authorisation") + " policies");
            }
            added.add(e.getKey());
        }
    }

    /** Authorisations first, so that no obligation policy acts before the rules that govern it apply. */
    private void activate(RoleObject object) {
        for (String name : newAuthorisations) {
            ((PolicyHandle) object.part(RoleObject.AUTH).get(name)).active(true);
        }
        for (String name : newPolicies) {
            ((PolicyHandle) object.part(RoleObject.POLICY).get(name)).active(true);
        }
    }

    private void startTasks() throws RoleLoadException {
        for (Map.Entry<String, Task> e : newTasks.entrySet()) {
            started.add(e.getValue());
            try {
                e.getValue().start();
            } catch (RuntimeException failure) {
                throw fail("task '" + e.getKey() + "'", "it failed to start: " + failure);
            }
        }
    }

    private void rollBack(TreeSnapshot base) {
        for (Task task : bound) {
            task.unbind();
        }
        for (Task task : started) {
            try {
                task.stop();
            } catch (RuntimeException ignored) {
                // The load is failing already; its reason is the one to report.
            }
        }
        for (Handle policy : created) {
            Policies.retire(policy);
        }
        base.restore(root);
    }

    private LoadedRole commit(RoleObject object) {
        LoadedRole record = existing != null ? existing : new LoadedRole(object);
        object.describe(role);
        record.sources.addAll(sourcesRun);
        record.tasks.putAll(newTasks);
        record.bound.addAll(bound);
        record.madeDomains.addAll(madeDomains);
        record.outside.addAll(outside);
        return record;
    }

    private List<String> reasons(RunResult result) {
        List<String> reasons = new ArrayList<>();
        for (Diagnostic d : result.diagnostics()) {
            reasons.add(d.toString());
        }
        if (reasons.isEmpty()) {
            reasons.add("it ended with " + result.status());
        }
        return reasons;
    }

    private RoleLoadException fail(String part, String reason) {
        return new RoleLoadException(role.name(), part, List.of(reason));
    }
}
