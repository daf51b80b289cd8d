package net.smc.core.cell;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.TreeSet;
import java.util.function.Consumer;
import java.util.function.Predicate;
import java.util.function.Supplier;

import net.smc.core.mission.MissionRole;
import net.smc.core.mission.RoleInterface;
import net.smc.core.role.ExternalInterface;
import net.smc.core.role.LocalInterface;
import net.smc.core.role.PolicySource;
import net.smc.core.role.RequiredOperation;
import net.smc.core.role.Role;
import net.smc.core.role.TaskOperation;
import net.smc.core.role.TaskProvider;
import net.smc.core.task.StateHandover;
import net.smc.core.task.Task;
import net.smc.policy.api.Diagnostic;

/**
 * A cell's roles as this vehicle runs them: a role of the mission built for it (the policies as
 * the cell holds them, the vehicle's tasks, the role's interfaces), the events its tasks raise
 * published through the first held role that publishes them, and the state of its running tasks,
 * exported to be handed over when a role moves to another vehicle and imported when one arrives.
 * {@link Cell} wires it; it holds nothing of the team's state.
 */
final class VehicleRoles {
    /** The key that starts one task's entry in the handed-over state. */
    private static final String TASK_STATE = "#task";

    /** Publishes a role's event to the team; answers how many neighbours it went to. */
    interface Publisher {
        int publish(String role, String event, List<Object> values);
    }

    private final String vehicle;
    private final Slots slots;
    private final TaskProvider tasks;
    private final Supplier<List<Seat>> seats;
    private final Predicate<String> loaded;
    private final Publisher publisher;
    private final Consumer<Diagnostic> errors;

    /**
     * @param seats the seats the vehicle holds, primary first
     * @param loaded whether a role is loaded in the cell's Role-Manager
     * @param errors where a task's refusal of handed-over state is reported
     */
    VehicleRoles(String vehicle, Slots slots, TaskProvider tasks, Supplier<List<Seat>> seats, Predicate<String> loaded,
                 Publisher publisher, Consumer<Diagnostic> errors) {
        this.vehicle = vehicle;
        this.slots = slots;
        this.tasks = tasks;
        this.seats = seats;
        this.loaded = loaded;
        this.publisher = publisher;
        this.errors = errors;
    }

    /** The first role this cell holds whose mission interface publishes {@code event}. */
    Optional<String> publishingRole(String event) {
        for (Seat s : seats.get()) {
            if (slots.role(s.role()).interfaces().publishes().contains(event) && loaded.test(s.role())) {
                return Optional.of(s.role());
            }
        }
        return Optional.empty();
    }

    private void taskRaised(Task task, String event, List<Object> values) {
        publishingRole(event).ifPresent(role -> publisher.publish(role, event, values));
    }

    /** Per running task that hands state over: {@code ["#task", name, key, value, ...]}. */
    List<Object> taskStates() {
        List<Object> out = new ArrayList<>();
        if (tasks == TaskProvider.NONE) {
            return out;
        }
        for (String name : new TreeSet<>(tasks.names())) {
            Optional<Task> t = tasks.task(name);
            if (t.isPresent() && t.get().isRunning() && t.get() instanceof StateHandover h) {
                List<Object> entry = new ArrayList<>();
                entry.add(TASK_STATE);
                entry.add(name);
                h.exportState().forEach((k, v) -> {
                    entry.add(k);
                    entry.add(WireValues.of(v));
                });
                out.add(entry);
            }
        }
        return out;
    }

    /** Gives the tasks of {@code role} the state handed over with it; a task that refuses it is reported. */
    void importTaskStates(String role, List<Object> handedOver) {
        Set<String> ofRole = slots.role(role).requirement().tasks();
        for (Object o : handedOver) {
            if (o instanceof List<?> l && l.size() >= 2 && TASK_STATE.equals(l.get(0)) && l.get(1) instanceof String name
                    && ofRole.contains(name)) {
                Optional<Task> t = tasks.task(name);
                if (t.isPresent() && t.get() instanceof StateHandover h) {
                    Map<String, Object> state = new LinkedHashMap<>();
                    for (int i = 2; i + 1 < l.size(); i += 2) {
                        state.put(String.valueOf(l.get(i)), WireValues.toJava(l.get(i + 1)));
                    }
                    try {
                        h.importState(state);
                    } catch (RuntimeException bad) {
                        errors.accept(new Diagnostic(new net.smc.policy.lang.SourcePos("handover", 1, 1), "task " + name
                                + " of role '" + role + "' refused the handed-over state: " + bad.getMessage()));
                    }
                }
            }
        }
    }

    /** The role a vehicle loads for {@code name}: the mission's policies as this cell holds them, and its tasks. */
    Role roleOf(String name, PolicyStore from) {
        MissionRole r = slots.role(name);
        Role.Builder b = Role.builder(name);
        for (String uri : r.policies()) {
            b.mission(PolicySource.text(uri, text(from, uri, name)));
        }
        for (String uri : r.authorisations()) {
            b.authorisation(PolicySource.text(uri, text(from, uri, name)));
        }
        slots.managedRoles(name).forEach(b::manages);
        boolean withTasks = tasks != TaskProvider.NONE;
        if (withTasks) {
            for (String task : new TreeSet<>(r.requirement().tasks())) {
                b.task(task, () -> {
                    Task t = tasks.task(task).orElseThrow(() -> new IllegalStateException("vehicle '" + vehicle
                            + "' has no task '" + task + "' (its tasks: " + new TreeSet<>(tasks.names()) + ")"));
                    t.listen(this::taskRaised);
                    return t;
                });
            }
        }
        // The mission's <interface>: operations only where the role runs its tasks here.
        RoleInterface in = r.interfaces();
        List<TaskOperation> offered = withTasks
                ? in.offers().stream().map(o -> new TaskOperation(o.task(), o.selector())).toList() : List.of();
        b.local(new LocalInterface(offered, in.publishes()));
        b.external(new ExternalInterface(offered, in.publishes(),
                in.uses().stream().map(u -> new RequiredOperation(u.role(), u.selector())).toList(), in.subscribes()));
        return b.build();
    }

    private static String text(PolicyStore from, String uri, String role) {
        return from.get(uri, PolicyStore.ANY_VERSION).orElseThrow(() -> new IllegalStateException("policy " + uri
                + " of role '" + role + "' has not arrived")).text();
    }
}
