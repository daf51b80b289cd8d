package net.smc.sim.task;

import net.smc.core.task.Attr;
import net.smc.core.task.TaskEvent;
import net.smc.core.task.TaskInterface;
import net.smc.policy.api.Op;

/** The task interface of {@link Navigator}: go to a point on the map, around obstacles and avoided zones. */
@TaskInterface("Navigator")
public interface NavigatorI {

    /** Plans a path to {@code (x, y)} and drives along it; ends with {@link #arrived} or {@link #blocked}. */
    @Op("goTo:y:")
    void goTo(double x, double y);

    /** Adds a circular zone the robot must not enter (nor come within the margin of). */
    @Op("avoid:y:radius:")
    void avoid(double x, double y, double radius);

    /** Forgets every avoided zone. */
    @Op("clearZones")
    void clearZones();

    /** Sets the margin kept around avoided zones, metres (default 0.5). */
    @Op("margin:")
    void margin(double metres);

    /**
     * A failed teammate's body lies at (x, y) (its last reported position): when no path goes
     * around it, the robot plans through the body's cells and drives slowly into it to push it
     * aside (a dead robot in a doorway would otherwise seal the rooms behind it).
     */
    @Op("pushAside:y:")
    void pushAside(double x, double y);

    /** Gives up the current goal and stops. */
    @Op("halt")
    void halt();

    /** Whether a goal is being pursued. */
    @Op("isMoving")
    boolean isMoving();

    /** The goal was reached (within the arrival tolerance). */
    @TaskEvent
    void arrived(@Attr("x") double x, @Attr("y") double y);

    /** The goal cannot be reached: no path on the map, or no progress along it. */
    @TaskEvent
    void blocked(@Attr("x") double x, @Attr("y") double y);
}
