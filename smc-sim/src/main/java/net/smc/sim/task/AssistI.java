package net.smc.sim.task;

import net.smc.core.task.Attr;
import net.smc.core.task.TaskEvent;
import net.smc.core.task.TaskInterface;
import net.smc.policy.api.Op;

/** The task interface of {@link Assist}: deliver assistance to the soldier once within reach. */
@TaskInterface("Assist")
public interface AssistI {

    /** The soldier is at {@code (x, y)}: assist once within reach. */
    @Op("assist:y:")
    void assist(double x, double y);

    /** Sets the reach, metres (default 1). */
    @Op("reach:")
    void reach(double metres);

    /** Whether assistance was delivered for the current call. */
    @Op("hasAssisted")
    boolean hasAssisted();

    /** Assistance was delivered to the soldier at {@code (x, y)}. */
    @TaskEvent
    void assisted(@Attr("x") double x, @Attr("y") double y);
}
