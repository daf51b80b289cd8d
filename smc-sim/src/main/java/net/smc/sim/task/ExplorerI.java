package net.smc.sim.task;

import net.smc.core.task.Attr;
import net.smc.core.task.TaskEvent;
import net.smc.core.task.TaskInterface;
import net.smc.policy.api.Op;

/** The task interface of {@link Explorer}: explore the arena into the robot's map. */
@TaskInterface("Explorer")
public interface ExplorerI {

    /** Starts (or resumes) frontier exploration. */
    @Op("explore")
    void explore();

    /** Stops exploring and the robot with it; the map keeps being filled while the task runs. */
    @Op("halt")
    void halt();

    /** The share of the map known, 0..1. */
    @Op("exploredFraction")
    double exploredFraction();

    /** Whether reachable frontiers remain to explore. */
    @Op("isExploring")
    boolean isExploring();

    /** The infrared ring found an obstacle at a map cell not reported before. */
    @TaskEvent
    void obstacle(@Attr("x") double x, @Attr("y") double y);

    /** The explored share passed another tenth, or exploring ended ({@code done}: no reachable frontier left). */
    @TaskEvent
    void areaExplored(@Attr("fraction") double fraction, @Attr("done") boolean done);

    /** The camera saw a tagged object for the first time, at {@code (x, y)}. */
    @TaskEvent
    void targetSighted(@Attr("tag") String tag, @Attr("kind") String kind, @Attr("x") double x, @Attr("y") double y);
}
