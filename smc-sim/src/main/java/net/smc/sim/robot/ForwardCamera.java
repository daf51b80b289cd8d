package net.smc.sim.robot;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;

import net.smc.sim.hardware.Camera;
import net.smc.sim.hardware.Pose;
import net.smc.sim.hardware.Sighting;
import net.smc.sim.arena.Arena;

/**
 * A camera at the front of the body, looking along the heading: it reports the tagged things
 * (targets such as the soldier, hazards, open doors, other robots) whose centre lies within its
 * range and field of view and in its line of sight (walls, closed doors and obstacles occlude;
 * robots, hazards and targets do not), with seeded noise on bearing and distance.
 */
final class ForwardCamera implements Camera {
    private final SimRobot robot;
    private double lookCos;   // the heading's cosine and sine during look()
    private double lookSin;
    private double edgeCos;   // the cosine of half the field of view, a hair wider

    ForwardCamera(SimRobot robot) {
        this.robot = robot;
    }

    @Override
    public double fieldOfView() {
        return robot.spec().cameraFov();
    }

    @Override
    public double range() {
        return robot.spec().cameraRange();
    }

    @Override
    public List<Sighting> look() {
        RobotGround ground = robot.ground();
        Arena arena = ground.arena();
        Pose p = robot.pose();
        double cx = p.x() + robot.spec().length() / 2 * Math.cos(p.heading());
        double cy = p.y() + robot.spec().length() / 2 * Math.sin(p.heading());
        lookCos = Math.cos(p.heading());
        lookSin = Math.sin(p.heading());
        edgeCos = Math.cos(robot.spec().cameraFov() / 2 + 1e-9);
        List<Sighting> seen = new ArrayList<>();
        int candidate = 0;
        for (Arena.Target t : arena.targets()) {
            consider(seen, candidate++, cx, cy, p.heading(), "", t.id(), t.kind(), t.x(), t.y());
        }
        for (Arena.Hazard h : arena.hazards()) {
            consider(seen, candidate++, cx, cy, p.heading(), "hazard:", h.id(), "hazard", h.x(), h.y());
        }
        for (Arena.Door d : arena.doors()) {
            if (d.open()) {
                consider(seen, candidate, cx, cy, p.heading(), "door:", d.id(), "marker", (d.x1() + d.x2()) / 2,
                        (d.y1() + d.y2()) / 2);
            }
            candidate++;
        }
        for (SimRobot other : ground.robots()) {
            if (other != robot) {
                consider(seen, candidate, cx, cy, p.heading(), "", other.id(), "robot", other.x(), other.y());
            }
            candidate++;
        }
        seen.sort(Comparator.comparingDouble(Sighting::distance).thenComparing(Sighting::tag));
        return seen;
    }

    /** Adds a sighting of the thing tagged {@code prefix + id} at (x, y) when the camera sees it. */
    private void consider(List<Sighting> seen, int candidate, double cx, double cy, double heading, String prefix,
                          String id, String kind, double x, double y) {
        KoalaSpec spec = robot.spec();
        double dx = x - cx;
        double dy = y - cy;
        double range = spec.cameraRange();
        double d2 = dx * dx + dy * dy;
        if (d2 > range * range * (1 + 1e-9)) {
            return;   // clearly out of range: spare the exact tests below
        }
        if (spec.cameraFov() < Math.PI && d2 > 0
                && dx * lookCos + dy * lookSin < edgeCos * Math.sqrt(d2)) {
            return;   // clearly outside the field of view
        }
        double distance = Math.hypot(dx, dy);
        if (distance > range) {
            return;
        }
        double bearing = Math.IEEEremainder(Math.atan2(y - cy, x - cx) - heading, 2 * Math.PI);
        if (Math.abs(bearing) > spec.cameraFov() / 2 || !robot.ground().clearLine(cx, cy, x, y)) {
            return;
        }
        int channel = SimRobot.Channels.CAMERA + 2 * candidate;
        double noisyDistance = distance + spec.cameraNoise()
                * robot.ground().gaussian(robot.stream(), channel);
        double noisyBearing = bearing + spec.cameraNoise() / 10
                * robot.ground().gaussian(robot.stream(), channel + 1);
        String tag = prefix.isEmpty() ? id : prefix + id;
        seen.add(new Sighting(tag, kind, noisyBearing, Math.max(0, noisyDistance)));
    }
}
