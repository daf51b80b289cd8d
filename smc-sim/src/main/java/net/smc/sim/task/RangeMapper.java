package net.smc.sim.task;

import java.util.ArrayList;
import java.util.List;
import net.smc.sim.hardware.Pose;
import net.smc.sim.hardware.ProximitySensors;
import net.smc.sim.hardware.RobotHardware;
import net.smc.sim.map.OccupancyGrid;
import net.smc.sim.map.Point;

/**
 * Fills an occupancy grid from the infrared ring and the odometry. The sensors read from the
 * body's edge; the body's radius is taken as half the wheel base (the wheels sit at its edge).
 * Each beam marks the cells it crosses free and, when it hits something, its end occupied. Between
 * two neighbouring beams: when both hit something and their two hit points lie within
 * {@link #SAME_SURFACE} of each other (closer than a robot is wide, so no way through is closed),
 * one surface is taken to run between them, and rays in between end on it; otherwise the wedge is
 * marked free up to the nearer of the two readings (nothing that both beams pass is taken to hide
 * between them).
 */
final class RangeMapper {
    /** How close two neighbouring beams' hit points must be for one surface to be taken to join them, m. */
    static final double SAME_SURFACE = 0.3;
    /** How far short of a hit a ray marks nothing free, m. */
    static final double HIT_SHADOW = 0.35;

    private RangeMapper() {
    }

    /** The distance between the ends of two rays of lengths {@code a} and {@code b}, {@code angle} apart. */
    private static double gap(double a, double b, double angle) {
        return Math.sqrt(Math.max(0, a * a + b * b - 2 * a * b * Math.cos(angle)));
    }

    /**
     * One ray of {@code length} from the robot's centre at angle {@code a}. A ray that hits marks
     * free only up to {@link #HIT_SHADOW} short of the hit: the last cells before a hit are the
     * ones a ray at a shallow angle to a wall crosses just beside it, and marking them free would
     * wear the wall away. Nor does it mark free beyond where it first comes within that distance of
     * one of {@code shadows} (other hits of the same reading; none for {@link #observe}).
     */
    private static void ray(OccupancyGrid map, Pose pose, double a, double length, boolean hit, List<Point> shadows) {
        double cos = Math.cos(a);
        double sin = Math.sin(a);
        double free = Math.min(hit ? length - HIT_SHADOW : length, clearOf(pose, cos, sin, shadows));
        if (free > 0) {
            map.observeRay(pose.x(), pose.y(), pose.x() + cos * free, pose.y() + sin * free, false);
        }
        if (hit) {
            map.markOccupied(pose.x() + cos * length, pose.y() + sin * length);
        }
    }

    /**
     * How far a ray from the robot in direction (cos, sin) goes before it first comes within
     * {@link #HIT_SHADOW} of one of {@code shadows} (infinity when it never does).
     */
    private static double clearOf(Pose pose, double cos, double sin, List<Point> shadows) {
        double best = Double.POSITIVE_INFINITY;
        if (shadows == null) {
            return best;
        }
        for (Point h : shadows) {
            double dx = h.x() - pose.x();
            double dy = h.y() - pose.y();
            double along = dx * cos + dy * sin;
            double across = Math.abs(-dx * sin + dy * cos);
            if (along > 0 && across < HIT_SHADOW) {
                best = Math.min(best, Math.max(0, along - Math.sqrt(HIT_SHADOW * HIT_SHADOW - across * across)));
            }
        }
        return best;
    }

    /** Adds the current readings to {@code map}; answers where the sensors hit something. */
    static List<Point> observe(RobotHardware robot, OccupancyGrid map) {
        return observe(robot, map, false);
    }

    /**
     * Adds the current readings to {@code map} as {@link #observe} does, except that no ray marks
     * a cell free within {@link #HIT_SHADOW} of any point the ring hits (not only of its own hit):
     * for a map to drive on. A wall on the line between two grid columns lies on the edge of the
     * cells beside it, and a ray at a shallow angle to the wall, hitting it farther along, crosses
     * those cells short of its own hit's shadow; as the robot moved, such rays freed the cells the
     * ring had marked a moment before, and the map showed gaps in the wall that a planner took for
     * ways through it. A neighbouring beam hits the wall nearer, and its shadow now covers them.
     * Not covered: a ray that reaches its full range without a hit and ends beside the wall, with
     * no hit near it (a robot half a metre or more from the wall still frees some of those cells).
     * The Explorer keeps {@link #observe}: its map is the one that counts the floor mapped, and
     * floor beside a wall is mostly marked by those rays.
     */
    static List<Point> observeKeepingWalls(RobotHardware robot, OccupancyGrid map) {
        return observe(robot, map, true);
    }

    private static List<Point> observe(RobotHardware robot, OccupancyGrid map, boolean keepWalls) {
        List<Point> hits = new ArrayList<>();
        if (!robot.has(RobotHardware.Device.PROXIMITY)) {
            return hits;
        }
        ProximitySensors ir = robot.proximity();
        Pose pose = robot.odometry().pose();
        double body = robot.drive().wheelBase() / 2;
        double[] readings = ir.read();
        double range = ir.range();
        List<Point> shadows = keepWalls ? new ArrayList<>() : null;
        if (keepWalls) {
            for (int i = 0; i < readings.length; i++) {
                double d = Math.max(0, Math.min(range, readings[i]));
                if (d < range - 1e-6) {
                    double a = pose.heading() + ir.angle(i);
                    shadows.add(new Point(pose.x() + Math.cos(a) * (body + d), pose.y() + Math.sin(a) * (body + d)));
                }
            }
        }
        for (int i = 0; i < readings.length; i++) {
            int j = (i + 1) % readings.length;
            double a0 = ir.angle(i);
            double span = Math.IEEEremainder(ir.angle(j) - a0, 2 * Math.PI);
            double di = Math.max(0, Math.min(range, readings[i]));
            double dj = Math.max(0, Math.min(range, readings[j]));
            boolean surface = di < range - 1e-6 && dj < range - 1e-6 && gap(body + di, body + dj, span) <= SAME_SURFACE;
            double near = Math.min(di, dj);
            int between = (int) Math.ceil(Math.abs(span) * (body + Math.max(di, dj)) / map.resolution());
            for (int k = 1; k < between; k++) {
                double t = (double) k / between;
                double a = pose.heading() + a0 + span * t;
                if (surface) {
                    ray(map, pose, a, body + di + (dj - di) * t, true, shadows);
                } else {
                    // free up to the nearer reading, less the shadow when that reading is a hit
                    double d = Math.min(body + near - (near < range - 1e-6 ? HIT_SHADOW : 0),
                            clearOf(pose, Math.cos(a), Math.sin(a), shadows));
                    if (d > 0) {
                        map.observeRay(pose.x(), pose.y(), pose.x() + Math.cos(a) * d, pose.y() + Math.sin(a) * d, false);
                    }
                }
            }
        }
        for (int i = 0; i < readings.length; i++) {
            double a = pose.heading() + ir.angle(i);
            double d = Math.max(0, Math.min(range, readings[i]));
            boolean hit = d < range - 1e-6;
            double ex = pose.x() + Math.cos(a) * (body + d);
            double ey = pose.y() + Math.sin(a) * (body + d);
            ray(map, pose, a, body + d, hit, shadows);
            if (hit) {
                hits.add(new Point(ex, ey));
            }
        }
        return hits;
    }
}
