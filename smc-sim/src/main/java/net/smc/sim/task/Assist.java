package net.smc.sim.task;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import net.smc.sim.hardware.Pose;
import net.smc.sim.hardware.RobotHardware;
import net.smc.sim.hardware.Sighting;
import net.smc.sim.map.Point;

/**
 * Delivers assistance to the soldier: once told where the soldier is, it raises {@code assisted}
 * (once per call) as soon as the robot is within reach, by its odometry or because the camera sees
 * the soldier within reach. Getting there is the Navigator's job; the policies tie the two.
 */
public final class Assist extends RobotTask implements AssistI, Handover {
    private Point soldier;
    private double reach = 1.0;
    private boolean done;

    public Assist(TaskContext context) {
        this(context.hardware());
    }

    public Assist(RobotHardware hardware) {
        super(hardware);
    }

    @Override
    public void assist(double x, double y) {
        soldier = new Point(x, y);
        done = false;
    }

    @Override
    public void reach(double metres) {
        if (!(metres > 0) || !Double.isFinite(metres)) {
            throw new IllegalArgumentException("Assist reach " + metres + " must be a positive number of metres");
        }
        reach = metres;
    }

    @Override
    public boolean hasAssisted() {
        return done;
    }

    @Override
    public void assisted(double x, double y) {
        raise("assisted", x, y);
    }

    @Override
    protected void step(double time, double dt) {
        if (soldier == null || done) {
            return;
        }
        Pose pose = hardware.odometry().pose();
        boolean near = soldier.distanceTo(pose.x(), pose.y()) <= reach;
        if (!near && hardware.has(RobotHardware.Device.CAMERA)) {
            for (Sighting s : hardware.camera().look()) {
                if (s.kind().equals("soldier") && s.distance() <= reach) {
                    near = true;
                    break;
                }
            }
        }
        if (near) {
            done = true;
            assisted(soldier.x(), soldier.y());
        }
    }

    /** {@code soldier}: [x, y] while a call is open; {@code reach}. */
    @Override
    public Map<String, Object> exportState() {
        Map<String, Object> state = new LinkedHashMap<>();
        if (soldier != null && !done) {
            state.put("soldier", List.of(soldier.x(), soldier.y()));
        }
        state.put("reach", reach);
        return state;
    }

    @Override
    public void importState(Map<String, ?> state) {
        if (StateValues.has(state, "reach")) {
            reach(StateValues.number("Assist", state, "reach"));
        }
        if (StateValues.has(state, "soldier")) {
            List<?> s = StateValues.list("Assist", state, "soldier");
            if (s.size() != 2 || !(s.get(0) instanceof Number x) || !(s.get(1) instanceof Number y)) {
                throw new IllegalArgumentException("Assist state: 'soldier' must be [x, y], got " + s);
            }
            assist(x.doubleValue(), y.doubleValue());
        }
    }
}
