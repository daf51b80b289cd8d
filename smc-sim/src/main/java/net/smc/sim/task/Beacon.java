package net.smc.sim.task;

import java.util.LinkedHashMap;
import java.util.Map;
import net.smc.sim.hardware.Pose;
import net.smc.sim.hardware.RobotHardware;

/**
 * The soldier's beacon: once told the soldier's condition it raises {@code distress} with the
 * position its odometry gives, at once and then every period while it runs, until cancelled.
 */
public final class Beacon extends RobotTask implements BeaconI, Handover {
    private String condition;
    private double period = 10;
    private double nextCall = Double.NaN;
    private boolean pending;

    public Beacon(TaskContext context) {
        this(context.hardware());
    }

    public Beacon(RobotHardware hardware) {
        super(hardware);
    }

    @Override
    public void raiseDistress(String condition) {
        if (condition == null || condition.isBlank()) {
            throw new IllegalArgumentException("Beacon distress: the condition must not be blank");
        }
        this.condition = condition;
        if (isRunning()) {
            call();
        } else {
            pending = true;
        }
    }

    @Override
    public void cancel() {
        condition = null;
        pending = false;
        nextCall = Double.NaN;
    }

    @Override
    public void period(double seconds) {
        if (!(seconds > 0) || !Double.isFinite(seconds)) {
            throw new IllegalArgumentException("Beacon period " + seconds + " must be a positive number of seconds");
        }
        period = seconds;
    }

    @Override
    public boolean isCalling() {
        return condition != null;
    }

    @Override
    public void distress(double x, double y, String condition) {
        raise("distress", x, y, condition);
    }

    private void call() {
        Pose pose = hardware.odometry().pose();
        pending = false;
        nextCall = Double.NaN;
        distress(pose.x(), pose.y(), condition);
    }

    @Override
    protected void step(double time, double dt) {
        if (condition == null) {
            return;
        }
        if (pending) {
            call();
        }
        if (Double.isNaN(nextCall)) {
            nextCall = time + period;
        } else if (time >= nextCall) {
            call();
            nextCall = time + period;
        }
    }

    /** {@code condition} when calling; {@code period}. */
    @Override
    public Map<String, Object> exportState() {
        Map<String, Object> state = new LinkedHashMap<>();
        if (condition != null) {
            state.put("condition", condition);
        }
        state.put("period", period);
        return state;
    }

    @Override
    public void importState(Map<String, ?> state) {
        if (StateValues.has(state, "period")) {
            period(StateValues.number("Beacon", state, "period"));
        }
        if (StateValues.has(state, "condition")) {
            raiseDistress(StateValues.string("Beacon", state, "condition"));
        }
    }
}
