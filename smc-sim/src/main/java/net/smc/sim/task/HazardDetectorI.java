package net.smc.sim.task;

import java.util.List;
import net.smc.core.task.Attr;
import net.smc.policy.api.ArrayValue;
import net.smc.core.task.TaskEvent;
import net.smc.core.task.TaskInterface;
import net.smc.policy.api.Op;

/** The task interface of {@link HazardDetector}: report hazards the chemical sensor finds. */
@TaskInterface("HazardDetector")
public interface HazardDetectorI {

    /** The strength (0..1) at which a sensed hazard is reported (default 0.5). */
    @Op("threshold:")
    void threshold(double strength);

    /**
     * Goes to confirm a suspected hazard near (x, y): drives towards it (keeping out of the hazards
     * it has confirmed) until the sensor reads the threshold, or it is there, or no way is left.
     * Points asked for while one is inspected are queued, nearest first; one within a metre of a
     * queued point or a confirmed hazard is ignored.
     */
    @Op("inspect:y:")
    void inspect(double x, double y);

    /**
     * Fills the unknown cells of the robot's own map, on which it plans its way to the points to
     * inspect, from another's, given as its rows ({@code mapUpdate}'s {@code cells}); what its own
     * sensors saw stands.
     */
    @Op("merge:")
    void merge(ArrayValue cells);

    /**
     * A failed teammate's body lies at (x, y) (its last reported position): on its way to a point
     * to inspect the robot goes around the body when there is room, else it plans through the
     * body's cells and pushes it aside (a dead robot in a doorway would otherwise keep it out of
     * the room beyond). A detector without a map does not drive and ignores it.
     */
    @Op("pushAside:y:")
    void pushAside(double x, double y);

    /** Whether it is inspecting or has points queued. */
    @Op("isInspecting")
    boolean isInspecting();

    /** The hazards reported so far, each {@code [tag, kind, x, y]}. */
    @Op("hazards")
    List<List<Object>> hazards();

    /**
     * A hazard was sensed at or above the threshold; {@code (x, y)} is where the robot stood. The
     * attributes are those of the architecture's {@code hazardDetected} template
     * (policies/boot/events.p2): {@code name} is the event's name, {@code uav} the detecting robot.
     */
    @TaskEvent
    void hazardDetected(@Attr("name") String name, @Attr("uav") String uav, @Attr("kind") String kind,
                        @Attr("x") double x, @Attr("y") double y);

    /**
     * An inspection ended: at (x, y), the point asked for, {@code found} tells whether a hazard was
     * sensed at the threshold on the way or there.
     */
    @TaskEvent
    void inspected(@Attr("x") double x, @Attr("y") double y, @Attr("found") boolean found);
}
