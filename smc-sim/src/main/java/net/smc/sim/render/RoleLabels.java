package net.smc.sim.render;

import java.util.Map;

/** The label drawn under a robot's id: its current role(s), as the team's cells say. */
@FunctionalInterface
public interface RoleLabels {

    /** No labels. */
    RoleLabels NONE = robotId -> null;

    /** The label of robot {@code robotId} now, or null (or "") for none. Called on the painting thread. */
    String label(String robotId);

    /** Labels from a map of robot id to label (read at each paint, so a live map may change). */
    static RoleLabels of(Map<String, String> labels) {
        return labels::get;
    }
}
