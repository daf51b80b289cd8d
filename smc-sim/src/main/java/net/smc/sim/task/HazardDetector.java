package net.smc.sim.task;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import net.smc.sim.hardware.ChemicalSensor;
import net.smc.sim.hardware.Pose;
import net.smc.sim.hardware.RobotHardware;

/**
 * Watches the chemical sensor while it runs and raises {@code hazardDetected} once per hazard (by
 * its tag), the first time the hazard is sensed at or above the threshold, at the robot's position
 * by its odometry. The sensor gives no bearing, so that position is the estimate: the stronger the
 * threshold, the nearer the hazard's centre.
 */
public final class HazardDetector extends RobotTask implements HazardDetectorI, Handover {
    private final Map<String, List<Object>> found = new LinkedHashMap<>();
    private double threshold = 0.5;

    public HazardDetector(TaskContext context) {
        this(context.hardware());
    }

    public HazardDetector(RobotHardware hardware) {
        super(hardware);
    }

    @Override
    public void threshold(double strength) {
        if (!(strength >= 0 && strength <= 1)) {
            throw new IllegalArgumentException("HazardDetector threshold " + strength + " must lie in 0..1");
        }
        threshold = strength;
    }

    @Override
    public List<List<Object>> hazards() {
        return List.copyOf(found.values());
    }

    @Override
    public void hazardDetected(String name, String uav, String kind, double x, double y) {
        raise("hazardDetected", name, uav, kind, x, y);
    }

    @Override
    protected void step(double time, double dt) {
        if (!hardware.has(RobotHardware.Device.CHEMICAL)) {
            return;
        }
        Pose pose = hardware.odometry().pose();
        for (ChemicalSensor.Reading r : hardware.chemical().sense()) {
            if (r.strength() >= threshold && !found.containsKey(r.tag())) {
                found.put(r.tag(), List.of(r.tag(), r.kind(), pose.x(), pose.y()));
                hazardDetected("hazardDetected", hardware.id(), r.kind(), pose.x(), pose.y());
            }
        }
    }

    /** {@code threshold}, and {@code hazards}: the reports so far, each [tag, kind, x, y]. */
    @Override
    public Map<String, Object> exportState() {
        Map<String, Object> state = new LinkedHashMap<>();
        state.put("threshold", threshold);
        state.put("hazards", new ArrayList<>(found.values()));
        return state;
    }

    /** Takes over the threshold and the reports (those hazards are not reported again). */
    @Override
    public void importState(Map<String, ?> state) {
        if (StateValues.has(state, "threshold")) {
            threshold(StateValues.number("HazardDetector", state, "threshold"));
        }
        if (StateValues.has(state, "hazards")) {
            for (Object o : StateValues.list("HazardDetector", state, "hazards")) {
                if (!(o instanceof List<?> h) || h.size() != 4 || !(h.get(0) instanceof String tag)
                        || !(h.get(1) instanceof String kind) || !(h.get(2) instanceof Number x)
                        || !(h.get(3) instanceof Number y)) {
                    throw new IllegalArgumentException("HazardDetector state: each of 'hazards' must be"
                            + " [tag, kind, x, y], got " + o);
                }
                found.putIfAbsent(tag, List.of(tag, kind, x.doubleValue(), y.doubleValue()));
            }
        }
    }
}
