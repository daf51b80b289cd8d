package net.smc.sim.render;

import java.awt.BasicStroke;
import java.awt.Graphics2D;
import java.awt.geom.Arc2D;
import java.awt.geom.Line2D;
import java.util.List;

import net.smc.sim.hardware.Pose;
import net.smc.sim.hardware.ProximitySensors;
import net.smc.sim.robot.SimRobot;
import net.smc.sim.arena.Arena;
import net.smc.sim.world.SimWorld;

/** Draws the sensor and radio overlays: camera cones, radio links, infrared rays. */
final class OverlayLayer {
    private OverlayLayer() {
    }

    /** Each working robot's camera: a translucent wedge of its field of view and range from the body's front. */
    static void cameraCones(Graphics2D g, SimWorld world, Viewport v) {
        g.setColor(Palette.CAMERA);
        for (SimRobot robot : world.robots()) {
            if (robot.disabled()) {
                continue;
            }
            Pose p = robot.pose();
            double fx = p.x() + robot.spec().length() / 2 * Math.cos(p.heading());
            double fy = p.y() + robot.spec().length() / 2 * Math.sin(p.heading());
            double r = v.px(robot.camera().range());
            double fov = Math.toDegrees(robot.camera().fieldOfView());
            double start = Math.toDegrees(p.heading()) - fov / 2;   // Arc2D: degrees counter-clockwise on screen
            g.fill(new Arc2D.Double(v.x(fx) - r, v.y(fy) - r, 2 * r, 2 * r, start, fov, Arc2D.PIE));
        }
    }

    /** A line per radio link between robots and stations, as opaque as the link is good. */
    static void radioLinks(Graphics2D g, SimWorld world, Viewport v) {
        List<SimRobot> robots = world.robots();
        List<Arena.Station> stations = world.arena().stations();
        g.setStroke(new BasicStroke(1.5f));
        for (int i = 0; i < robots.size(); i++) {
            SimRobot a = robots.get(i);
            for (int j = i + 1; j < robots.size(); j++) {
                SimRobot b = robots.get(j);
                link(g, v, world.radio().quality(a.id(), b.id()), a.x(), a.y(), b.x(), b.y());
            }
            for (Arena.Station s : stations) {
                link(g, v, world.radio().quality(a.id(), s.id()), a.x(), a.y(), s.x(), s.y());
            }
        }
    }

    private static void link(Graphics2D g, Viewport v, double quality, double ax, double ay, double bx, double by) {
        if (quality > 0) {
            g.setColor(Palette.alpha(Palette.RADIO, 0.15 + 0.75 * quality));
            g.draw(new Line2D.Double(v.x(ax), v.y(ay), v.x(bx), v.y(by)));
        }
    }

    /** Each working robot's infrared rays from the body's edge to what they read: red when they hit, faint when free. */
    static void irRays(Graphics2D g, SimWorld world, Viewport v) {
        g.setStroke(new BasicStroke(1f));
        for (SimRobot robot : world.robots()) {
            if (robot.disabled()) {
                continue;
            }
            Pose p = robot.pose();
            ProximitySensors ir = robot.proximity();
            double[] reading = ir.read();
            double half = Math.max(robot.spec().length(), robot.spec().width()) / 2;
            for (int i = 0; i < reading.length; i++) {
                double a = p.heading() + ir.angle(i);
                double edge = edge(robot, ir.angle(i));
                double from = Math.min(edge, half);
                double to = edge + reading[i];
                g.setColor(reading[i] < ir.range() ? Palette.IR_HIT : Palette.IR_FREE);
                g.draw(new Line2D.Double(v.x(p.x() + from * Math.cos(a)), v.y(p.y() + from * Math.sin(a)),
                        v.x(p.x() + to * Math.cos(a)), v.y(p.y() + to * Math.sin(a))));
            }
        }
    }

    /** The distance from a robot's centre to its body's edge in direction {@code angle} from its heading. */
    private static double edge(SimRobot robot, double angle) {
        double c = Math.abs(Math.cos(angle));
        double s = Math.abs(Math.sin(angle));
        return Math.min(c == 0 ? Double.MAX_VALUE : robot.spec().length() / 2 / c,
                s == 0 ? Double.MAX_VALUE : robot.spec().width() / 2 / s);
    }
}
