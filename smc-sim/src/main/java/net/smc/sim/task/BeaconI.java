package net.smc.sim.task;

import net.smc.core.task.Attr;
import net.smc.core.task.TaskEvent;
import net.smc.core.task.TaskInterface;
import net.smc.policy.api.Op;

/** The task interface of {@link Beacon}, the wounded soldier's: call for help. */
@TaskInterface("Beacon")
public interface BeaconI {

    /** Raises distress now with the soldier's condition ({@code wounded}, {@code critical} ...), and again every period until cancelled. */
    @Op("distress:")
    void raiseDistress(String condition);

    /** Stops calling for help. */
    @Op("cancel")
    void cancel();

    /** Sets how often distress repeats, seconds (default 10). */
    @Op("period:")
    void period(double seconds);

    /** Whether the beacon is calling. */
    @Op("isCalling")
    boolean isCalling();

    /** The soldier needs help at {@code (x, y)}. */
    @TaskEvent
    void distress(@Attr("x") double x, @Attr("y") double y, @Attr("condition") String condition);
}
