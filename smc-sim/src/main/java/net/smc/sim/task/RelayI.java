package net.smc.sim.task;

import java.util.List;
import net.smc.core.task.Attr;
import net.smc.core.task.TaskEvent;
import net.smc.core.task.TaskInterface;
import net.smc.policy.api.Op;

/** The task interface of {@link Relay}: keep the radio link to given peers above a threshold. */
@TaskInterface("Relay")
public interface RelayI {

    /** Adds a peer (a robot id) whose link must be kept. */
    @Op("keep:")
    void keep(String peer);

    /** Stops caring about a peer. */
    @Op("drop:")
    void drop(String peer);

    /** Tells where a peer is (from its reports), so the relay can head for it rather than search. */
    @Op("peer:x:y:")
    void peerAt(String peer, double x, double y);

    /** The link quality (0..1) below which the relay moves (default 0.5). */
    @Op("threshold:")
    void threshold(double quality);

    /** The peers kept, sorted. */
    @Op("peers")
    List<String> peers();

    /**
     * The link to a kept peer crossed the threshold (either way), or was first measured. The
     * attributes are those of the architecture's {@code linkQuality} template
     * (policies/boot/events.p2): {@code name} is the event's name, {@code uav} the far end.
     */
    @TaskEvent
    void linkQuality(@Attr("name") String name, @Attr("uav") String uav, @Attr("quality") double quality);
}
