package net.smc.sim.task;

import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import net.smc.sim.hardware.Pose;
import net.smc.sim.hardware.RobotHardware;
import net.smc.sim.hardware.Sighting;
import net.smc.sim.map.Point;

/**
 * Keeps the links to its peers: while the weakest kept link is below the threshold, the robot
 * moves to improve it, towards the peer's reported position if known, else towards the peer if
 * the camera sees it, else by gradient search (drive straight; when the link got worse over the
 * last second, or something is in the way, turn away by {@link #TUMBLE_DEGREES} and try again).
 * It stops once the link is back above the threshold plus a small hysteresis.
 */
public final class Relay extends RobotTask implements RelayI, Handover {
    /** How far the gradient search turns when the link got worse, degrees. */
    public static final double TUMBLE_DEGREES = 110;
    private static final double HYSTERESIS = 0.05;
    private static final double SAMPLE_PERIOD = 1.0;

    private final TreeMap<String, Point> peers = new TreeMap<>();
    private final Map<String, Boolean> above = new HashMap<>();
    private double threshold = 0.5;
    private boolean moving;
    private double lastQuality = Double.NaN;
    private double nextSample;
    private double turnTo = Double.NaN;

    public Relay(TaskContext context) {
        this(context.hardware());
    }

    public Relay(RobotHardware hardware) {
        super(hardware);
    }

    @Override
    public void keep(String peer) {
        if (peer == null || peer.isBlank()) {
            throw new IllegalArgumentException("Relay keep: a peer's id must not be blank");
        }
        peers.putIfAbsent(peer, null);
    }

    @Override
    public void drop(String peer) {
        peers.remove(peer);
        above.remove(peer);
    }

    @Override
    public void peerAt(String peer, double x, double y) {
        keep(peer);
        peers.put(peer, new Point(x, y));
    }

    @Override
    public void threshold(double quality) {
        if (!(quality >= 0 && quality <= 1)) {
            throw new IllegalArgumentException("Relay threshold " + quality + " must lie in 0..1");
        }
        threshold = quality;
    }

    @Override
    public List<String> peers() {
        return List.copyOf(peers.keySet());
    }

    @Override
    public void linkQuality(String name, String uav, double quality) {
        raise("linkQuality", name, uav, quality);
    }

    @Override
    protected boolean drives() {
        return true;
    }

    @Override
    protected void step(double time, double dt) {
        String weakest = null;
        double worst = Double.POSITIVE_INFINITY;
        for (String peer : peers.keySet()) {
            double q = hardware.radio().linkQuality(peer);
            Boolean was = above.get(peer);
            boolean is = q >= threshold;
            if (was == null || was != is) {
                above.put(peer, is);
                linkQuality("linkQuality", peer, q);
            }
            if (q < worst) {
                worst = q;
                weakest = peer;
            }
        }
        if (weakest == null || !hardware.drive().working()) {
            return;
        }
        if (!moving && worst < threshold) {
            moving = true;
            lastQuality = Double.NaN;
        } else if (moving && worst >= threshold + HYSTERESIS) {
            moving = false;
            turnTo = Double.NaN;
            hardware.drive().stop();
        }
        if (moving) {
            move(time, weakest, worst);
        }
    }

    private void move(double time, String peer, double quality) {
        Pose pose = hardware.odometry().pose();
        Point known = peers.get(peer);
        Double bearing = null;
        if (known != null) {
            bearing = PathFollower.angleDiff(Math.atan2(known.y() - pose.y(), known.x() - pose.x()), pose.heading());
        } else if (hardware.has(RobotHardware.Device.CAMERA)) {
            for (Sighting s : hardware.camera().look()) {
                if (s.tag().equals(peer)) {
                    bearing = s.bearing();
                    break;
                }
            }
        }
        boolean blocked = PathFollower.frontClearance(hardware) < 0.15;
        if (bearing == null) {
            if (time >= nextSample) {
                if (!Double.isNaN(lastQuality) && quality < lastQuality && Double.isNaN(turnTo)) {
                    turnTo = pose.heading() + Math.toRadians(TUMBLE_DEGREES);
                }
                lastQuality = quality;
                nextSample = time + SAMPLE_PERIOD;
            }
            if (blocked && Double.isNaN(turnTo)) {
                turnTo = pose.heading() + Math.toRadians(TUMBLE_DEGREES);
            }
            if (!Double.isNaN(turnTo)) {
                double error = PathFollower.angleDiff(turnTo, pose.heading());
                if (Math.abs(error) < Math.toRadians(5)) {
                    turnTo = Double.NaN;
                    lastQuality = Double.NaN;
                    nextSample = time + SAMPLE_PERIOD;
                } else {
                    bearing = error;
                }
            }
        }
        double error = bearing == null ? 0 : bearing;
        double max = hardware.drive().maxSpeed();
        double forward = Math.abs(error) > Math.toRadians(45) || blocked ? 0 : 0.6 * max * Math.cos(error);
        double turn = 2.0 * error * hardware.drive().wheelBase() / 2;
        hardware.drive().setWheelSpeeds(forward - turn, forward + turn);
    }

    /** {@code threshold}; {@code peers}: {id: [x, y]} where known, else {id: []}. */
    @Override
    public Map<String, Object> exportState() {
        Map<String, Object> state = new LinkedHashMap<>();
        state.put("threshold", threshold);
        Map<String, Object> list = new LinkedHashMap<>();
        peers.forEach((id, p) -> list.put(id, p == null ? List.of() : List.of(p.x(), p.y())));
        state.put("peers", list);
        return state;
    }

    @Override
    public void importState(Map<String, ?> state) {
        if (StateValues.has(state, "threshold")) {
            threshold(StateValues.number("Relay", state, "threshold"));
        }
        if (StateValues.has(state, "peers")) {
            for (Map.Entry<String, ?> e : StateValues.map("Relay", state, "peers").entrySet()) {
                if (e.getValue() instanceof List<?> l && l.size() == 2 && l.get(0) instanceof Number x
                        && l.get(1) instanceof Number y) {
                    peerAt(e.getKey(), x.doubleValue(), y.doubleValue());
                } else if (e.getValue() instanceof List<?> l && l.isEmpty()) {
                    keep(e.getKey());
                } else {
                    throw new IllegalArgumentException("Relay state: peer '" + e.getKey() + "' must map to [x, y] or [],"
                            + " got " + e.getValue());
                }
            }
        }
    }
}
