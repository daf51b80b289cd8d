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
     * wear the wall away.
     */
    private static void ray(OccupancyGrid map, Pose pose, double a, double length, boolean hit) {
        double cos = Math.cos(a);
        double sin = Math.sin(a);
        if (!hit) {
            map.observeRay(pose.x(), pose.y(), pose.x() + cos * length, pose.y() + sin * length, false);
            return;
        }
        double free = length - HIT_SHADOW;
        if (free > 0) {
            map.observeRay(pose.x(), pose.y(), pose.x() + cos * free, pose.y() + sin * free, false);
        }
        map.markOccupied(pose.x() + cos * length, pose.y() + sin * length);
    }

    /** Adds the current readings to {@code map}; answers where the sensors hit something. */
    static List<Point> observe(RobotHardware robot, OccupancyGrid map) {
        List<Point> hits = new ArrayList<>();
        if (!robot.has(RobotHardware.Device.PROXIMITY)) {
            return hits;
        }
        ProximitySensors ir = robot.proximity();
        Pose pose = robot.odometry().pose();
        double body = robot.drive().wheelBase() / 2;
        double[] readings = ir.read();
        double range = ir.range();
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
                    ray(map, pose, a, body + di + (dj - di) * t, true);
                } else {
                    // free up to the nearer reading, less the shadow when that reading is a hit
                    double d = body + near - (near < range - 1e-6 ? HIT_SHADOW : 0);
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
            ray(map, pose, a, body + d, hit);
            if (hit) {
                hits.add(new Point(ex, ey));
            }
        }
        return hits;
    }
}
