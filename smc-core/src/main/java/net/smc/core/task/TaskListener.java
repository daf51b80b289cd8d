package net.smc.core.task;

import java.util.List;

/**
 * Told of every event a bound task raises, after the cell's own policies have handled it. The
 * cell uses it to publish the events its roles publish to the roles of other vehicles.
 */
@FunctionalInterface
public interface TaskListener {

    /** {@code task} raised {@code event} with these values (Java values, in attribute order). */
    void raised(Task task, String event, List<Object> values);
}
