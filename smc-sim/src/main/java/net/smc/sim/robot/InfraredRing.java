package net.smc.sim.robot;

import net.smc.sim.hardware.Pose;
import net.smc.sim.hardware.ProximitySensors;

/**
 * Sixteen infrared proximity sensors on the body's edge, each a ray cast through the world: the
 * distance from the edge to the first body (wall, obstacle, robot, hazard, soldier) within range,
 * plus seeded Gaussian noise, clamped to [0, range]. Read again while nothing in the world moved and
 * no new noise was drawn ({@link RobotGround#moment()} unchanged: a navigating robot maps and
 * steers from the same step's readings), it gives the same readings without casting the rays again.
 */
final class InfraredRing implements ProximitySensors {
    /** Rays start this far inside the body, so that a sensor pressed against a wall still sees it. */
    private static final double INSET = 0.02;
    private final SimRobot robot;
    private final double[] edge;   // distance from the centre to the body's edge along each sensor
    private final double[] rayX;   // scratch: each ray's start and direction, and its hit distance
    private final double[] rayY;
    private final double[] rayAngle;
    private final double[] hits;
    private final double[] last;   // the last readings, and the world's moment they were taken at
    private long lastMoment = RobotGround.NO_MOMENT;

    InfraredRing(SimRobot robot) {
        this.robot = robot;
        KoalaSpec spec = robot.spec();
        edge = new double[spec.irCount()];
        for (int i = 0; i < edge.length; i++) {
            double a = spec.irAngle(i);
            double c = Math.abs(Math.cos(a));
            double s = Math.abs(Math.sin(a));
            edge[i] = Math.min(c == 0 ? Double.MAX_VALUE : spec.length() / 2 / c, s == 0 ? Double.MAX_VALUE : spec.width() / 2 / s);
        }
        rayX = new double[edge.length];
        rayY = new double[edge.length];
        rayAngle = new double[edge.length];
        hits = new double[edge.length];
        last = new double[edge.length];
    }

    @Override
    public int count() {
        return edge.length;
    }

    @Override
    public double angle(int i) {
        return robot.spec().irAngle(i);
    }

    @Override
    public double range() {
        return robot.spec().irRange();
    }

    @Override
    public double[] read() {
        long moment = robot.ground().moment();
        if (moment == lastMoment && moment != RobotGround.NO_MOMENT) {
            return last.clone();
        }
        KoalaSpec spec = robot.spec();
        Pose p = robot.pose();
        double range = spec.irRange();
        double[] out = new double[edge.length];
        for (int i = 0; i < edge.length; i++) {
            double direction = p.heading() + spec.irAngle(i);
            double from = edge[i] - INSET;
            rayX[i] = p.x() + from * Math.cos(direction);
            rayY[i] = p.y() + from * Math.sin(direction);
            rayAngle[i] = direction;
        }
        robot.ground().castRays(rayX, rayY, rayAngle, range + INSET, robot.body(), hits);
        for (int i = 0; i < edge.length; i++) {
            double hit = hits[i];
            if (Double.isInfinite(hit)) {
                out[i] = range;
            } else {
                double noisy = hit - INSET + spec.irNoise()
                        * robot.ground().gaussian(robot.stream(), SimRobot.Channels.INFRARED + i);
                out[i] = Math.max(0, Math.min(range, noisy));
            }
        }
        System.arraycopy(out, 0, last, 0, out.length);
        lastMoment = moment;
        return out;
    }
}
