package net.smc.sim.task;

import java.util.List;
import net.smc.core.task.Attr;
import net.smc.policy.api.ArrayValue;
import net.smc.core.task.TaskEvent;
import net.smc.core.task.TaskInterface;
import net.smc.policy.api.Op;

/** The task interface of {@link Aggregator}: one picture of the team's maps and hazard reports. */
@TaskInterface("Aggregator")
public interface AggregatorI {

    /** Reports a hazard; one of the same kind within the merge radius of a known one is the same hazard. */
    @Op("report:x:y:")
    void report(String kind, double x, double y);

    /**
     * Merges a robot's map, given as its rows ({@code mapUpdate}'s {@code cells}: one string per row
     * from the bottom, {@code ?} unknown, {@code .} free, {@code #} occupied), into the picture.
     */
    @Op("merge:")
    void merge(ArrayValue cells);

    /** The merged hazards, each {@code [kind, x, y, reports]} (the position is the mean of its reports). */
    @Op("hazards")
    List<List<Object>> hazards();

    /** The share of the merged map known, 0..1. */
    @Op("exploredFraction")
    double exploredFraction();

    /** Sets the radius within which reports of one kind are one hazard, metres (default 1). */
    @Op("mergeRadius:")
    void mergeRadius(double metres);

    /** A report named a hazard not known before. */
    @TaskEvent
    void hazardAdded(@Attr("kind") String kind, @Attr("x") double x, @Attr("y") double y);
}
