package net.smc.sim.task;

import java.util.List;
import net.smc.core.task.Attr;
import net.smc.core.task.TaskEvent;
import net.smc.core.task.TaskInterface;
import net.smc.policy.api.ArrayValue;
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

    /**
     * Keeps out of a circle from now on: no frontier inside it (grown by the robot's clearance) is
     * chosen and no path crosses it (a hazard seen from afar, say).
     */
    @Op("avoid:y:radius:")
    void avoid(double x, double y, double radius);

    /**
     * A failed teammate's body lies at (x, y) (its last reported position): when no frontier is
     * left open otherwise, the robot may plan through the cells of that body and drive slowly
     * into it to push it aside (a dead robot stopped in a doorway would otherwise seal the rooms
     * behind it). Zones to avoid stay closed.
     */
    @Op("pushAside:y:")
    void pushAside(double x, double y);

    /**
     * Raises {@code mapUpdate} with the map as it is now, if it changed since the last share (for
     * the aggregator, which merges the surveyors' maps).
     */
    @Op("shareMap")
    void shareMap();

    /**
     * Fills the unknown cells of the robot's map from another robot's, given as its rows
     * ({@code mapUpdate}'s {@code cells}); what its own sensors saw stands. Frontiers the other has
     * already mapped are then no longer frontiers here, so two surveyors sharing their maps do not
     * map the same rooms twice.
     */
    @Op("merge:")
    void merge(ArrayValue cells);

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

    /**
     * The robot's map: {@code cells} is one string per row from the bottom, one character per cell
     * ({@code ?} unknown, {@code .} free, {@code #} occupied: {@code OccupancyGrid#toState}). The
     * attributes are those of the architecture's {@code mapUpdate} template (policies/boot/events.p2).
     */
    @TaskEvent
    void mapUpdate(@Attr("name") String name, @Attr("uav") String uav, @Attr("cells") List<String> cells);
}
