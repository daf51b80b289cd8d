package net.smc.core.role;

import java.util.Objects;
import java.util.function.Supplier;
import net.smc.core.task.Task;

/**
 * One task of a role: the name it gets in the role's task domain
 * ({@code root/role/<role>/task/<name>}) and how to make it. A factory rather than an instance,
 * because a role description is reused for every vehicle that takes the role, while each vehicle
 * runs its own task.
 */
public record TaskBinding(String name, Supplier<? extends Task> factory) {
    public TaskBinding {
        RoleNames.check("task name", name);
        Objects.requireNonNull(factory, "factory of task '" + name + "'");
    }
}
