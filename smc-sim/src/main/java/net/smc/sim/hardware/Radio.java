package net.smc.sim.hardware;

import java.util.Map;

/** The robot's radio, as a task sees it: which robots it can hear and how well. */
public interface Radio {

    /**
     * The link quality to each robot in range now, 0 (no link) to 1 (perfect), by robot id;
     * robots out of range are absent.
     */
    Map<String, Double> neighbours();

    /** The link quality to one robot now, 0 when it is out of range or unknown. */
    default double linkQuality(String robotId) {
        return neighbours().getOrDefault(robotId, 0.0);
    }
}
