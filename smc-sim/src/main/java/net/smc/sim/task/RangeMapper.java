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
 */
final class RangeMapper {
    private RangeMapper() {
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
            double a = pose.heading() + ir.angle(i);
            double d = Math.max(0, Math.min(range, readings[i]));
            boolean hit = d < range - 1e-6;
            double ex = pose.x() + Math.cos(a) * (body + d);
            double ey = pose.y() + Math.sin(a) * (body + d);
            map.observeRay(pose.x(), pose.y(), ex, ey, hit);
            if (hit) {
                hits.add(new Point(ex, ey));
            }
        }
        return hits;
    }
}
