package net.smc.core.role;

import java.util.Collections;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import net.smc.core.task.Task;

/**
 * A vehicle's tasks, by name: where the cell finds the task instances a role's mission requires
 * ({@code <requires><task>} in the mission class) when the vehicle is assigned to the role. One
 * instance per name and vehicle: the Role-Manager starts it on assignment and stops it on
 * withdrawal, so a later assignment starts the same task again.
 */
public interface TaskProvider {

    /** A vehicle that runs no tasks: roles load without them. */
    TaskProvider NONE = of(Map.of());

    /**
     * The tasks of a map, by name: the map is read at each call (a caller may fill it later), and
     * never changed here.
     */
    static TaskProvider of(Map<String, ? extends Task> tasks) {
        return new TaskProvider() {
            @Override
            public Optional<Task> task(String name) {
                return Optional.ofNullable(tasks.get(name));
            }

            @Override
            public Set<String> names() {
                return Collections.unmodifiableSet(tasks.keySet());
            }
        };
    }

    /** The vehicle's task of that name, if it has one. */
    Optional<Task> task(String name);

    /** The names of the vehicle's tasks (for messages). */
    Set<String> names();
}
