package net.smc.sim.render;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.Shape;
import java.awt.geom.AffineTransform;
import java.awt.geom.Line2D;
import java.awt.geom.Path2D;
import java.awt.geom.Rectangle2D;
import java.awt.image.BufferedImage;
import java.util.List;

import net.smc.sim.hardware.Pose;
import net.smc.sim.robot.SimRobot;
import net.smc.sim.world.SimWorld;

/**
 * Draws a world as it is now, with a {@link Scene}, onto a {@code Graphics2D} of any size: the
 * arena (floor with a metre grid, walls, doors, obstacles), each hazard as a yellow disc inside the
 * translucent ring of its reach, the soldier, radio stations, each robot's trajectory, each robot
 * as an oriented rectangle in its own colour ({@link Palette#robot}, by the order it was added)
 * labelled with its id and role, a red X on each disabled robot and at each {@link Mark.Cross},
 * avoided zones as dashed circles, the chosen {@link Overlays}, a header with the title, caption
 * and mission time, a legend and a scale bar in metres. The world's x grows to the right and its
 * y upwards; {@link Viewport#fit} gives the transform, so tests can find a world point's pixel.
 *
 * <p>Reads the world without changing it (sensor reads for the infrared overlay draw no random
 * numbers of the run's own), so call it on the simulation's thread, between steps.
 */
public final class WorldPainter {

    /** Draws into a new opaque image of {@code width} x {@code height} pixels. */
    public BufferedImage render(SimWorld world, Scene scene, int width, int height) {
        BufferedImage image = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        try {
            paint(g, world, scene, width, height);
        } finally {
            g.dispose();
        }
        return image;
    }

    /**
     * Draws onto {@code g}, whose drawing area is {@code width} x {@code height} pixels from (0, 0).
     *
     * @return the transform from world metres to those pixels
     */
    public Viewport paint(Graphics2D g, SimWorld world, Scene scene, int width, int height) {
        Viewport v = Viewport.fit(world.arena(), width, height);
        Text text = new Text((int) Math.max(9, Math.min(20, v.header() * 0.48)));
        Overlays show = scene.overlays();
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
        g.setRenderingHint(RenderingHints.KEY_STROKE_CONTROL, RenderingHints.VALUE_STROKE_PURE);
        g.setColor(Palette.BACKGROUND);
        g.fill(new Rectangle2D.Double(0, 0, width, height));
        ArenaLayer.paint(g, world.arena(), v, text);
        if (scene.map() != null) {
            map(g, scene.map(), v);
        }
        if (show.cameraCones()) {
            OverlayLayer.cameraCones(g, world, v);
        }
        if (show.radioLinks()) {
            OverlayLayer.radioLinks(g, world, v);
        }
        if (show.trajectories() && scene.trajectories() != null) {
            trajectories(g, world, scene.trajectories(), v);
        }
        for (Mark mark : scene.marks()) {
            if (mark instanceof Mark.AvoidedZone zone) {
                avoidedZone(g, v, zone, text);
            }
        }
        List<SimRobot> robots = world.robots();
        // The names first: a robot is drawn over another's name, never hidden by it.
        for (int i = 0; i < robots.size(); i++) {
            SimRobot robot = robots.get(i);
            String role = scene.roles().label(robot.id());
            double x = v.x(robot.x()) + v.px(0.22);
            double y = v.y(robot.y()) - v.px(0.22);
            text.boldLabel(g, robot.id(), x, y, Palette.robot(i).darker());
            if (role != null && !role.isEmpty()) {
                text.label(g, role, x, y - text.size() - 1, Palette.robot(i).darker());
            }
        }
        for (int i = 0; i < robots.size(); i++) {
            robot(g, v, robots.get(i), Palette.robot(i));
        }
        if (show.irRays()) {
            OverlayLayer.irRays(g, world, v);
        }
        for (SimRobot robot : robots) {
            if (robot.disabled()) {
                cross(g, v, robot.x(), robot.y(), Math.max(robot.spec().length(), robot.spec().width()) * 0.6);
            }
        }
        for (Mark mark : scene.marks()) {
            if (mark instanceof Mark.Found found) {
                found(g, v, found, text);
            }
        }
        for (Mark mark : scene.marks()) {
            if (mark instanceof Mark.Cross cross) {
                cross(g, v, cross.x(), cross.y(), 0.2);
                text.label(g, cross.label(), v.x(cross.x()) + v.px(0.22), v.y(cross.y()) + v.px(0.22) + text.size(), Palette.MARK);
            }
        }
        if (show.legend()) {
            Decorations.scaleBar(g, world.arena(), v, text);
            Decorations.legend(g, world, scene, v, text);
        }
        Decorations.header(g, scene, world.time(), v, text);
        return v;
    }

    private static void trajectories(Graphics2D g, SimWorld world, TrajectoryRecorder recorder, Viewport v) {
        g.setStroke(new BasicStroke((float) Math.max(2, v.px(0.04)), BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
        List<SimRobot> robots = world.robots();
        for (int i = 0; i < robots.size(); i++) {
            List<TrajectoryRecorder.Point> path = recorder.path(robots.get(i).id());
            if (path.isEmpty()) {
                continue;
            }
            Path2D.Double line = new Path2D.Double();
            line.moveTo(v.x(path.get(0).x()), v.y(path.get(0).y()));
            for (TrajectoryRecorder.Point p : path.subList(1, path.size())) {
                line.lineTo(v.x(p.x()), v.y(p.y()));
            }
            if (!robots.get(i).disabled()) {
                line.lineTo(v.x(robots.get(i).x()), v.y(robots.get(i).y()));
            }
            g.setColor(Palette.robot(i));
            g.draw(line);
        }
    }

    /** The body, with a white notch at its front; a disabled robot's body is paler. */
    private static void robot(Graphics2D g, Viewport v, SimRobot robot, Color colour) {
        Pose p = robot.pose();
        double l = Math.max(6, v.px(robot.spec().length()));
        double w = Math.max(6, v.px(robot.spec().width()));
        AffineTransform at = new AffineTransform();
        at.translate(v.x(p.x()), v.y(p.y()));
        at.rotate(-p.heading());
        Shape body = at.createTransformedShape(new Rectangle2D.Double(-l / 2, -w / 2, l, w));
        g.setColor(robot.disabled() ? blend(colour, Color.WHITE, 0.35) : colour);
        g.fill(body);
        g.setColor(colour.darker().darker());
        g.setStroke(new BasicStroke(1.2f));
        g.draw(body);
        Path2D.Double notch = new Path2D.Double();
        notch.moveTo(l / 2 - 1, 0);
        notch.lineTo(l / 2 - l * 0.3, -w * 0.22);
        notch.lineTo(l / 2 - l * 0.3, w * 0.22);
        notch.closePath();
        g.setColor(Color.WHITE);
        g.fill(at.createTransformedShape(notch));
    }

    private static void avoidedZone(Graphics2D g, Viewport v, Mark.AvoidedZone zone, Text text) {
        double r = v.px(zone.radius());
        float dash = (float) Math.max(4, r / 6);
        g.setColor(Palette.ZONE);
        g.setStroke(new BasicStroke(2f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10f, new float[] {dash, dash * 0.7f}, 0f));
        g.draw(ArenaLayer.disc(v, zone.x(), zone.y(), r));
        text.label(g, zone.label(), v.x(zone.x()) - r * 0.7, v.y(zone.y()) - r - 4, Palette.ZONE);
    }

    /** Shades the cells the map does not know and tints the ones it holds occupied. */
    private static void map(Graphics2D g, net.smc.sim.map.OccupancyGrid map, Viewport v) {
        double side = v.px(map.resolution());
        for (int r = 0; r < map.rows(); r++) {
            for (int c = 0; c < map.cols(); c++) {
                Color colour = !map.isKnown(c, r) ? Palette.UNMAPPED : map.isOccupied(c, r) ? Palette.MAPPED_OBSTACLE : null;
                if (colour != null) {
                    double x = v.x(map.minX() + c * map.resolution());
                    double y = v.y(map.minY() + (r + 1) * map.resolution());
                    g.setColor(colour);
                    g.fill(new Rectangle2D.Double(x, y, side + 0.5, side + 0.5));
                }
            }
        }
    }

    /** A filled diamond with a dark edge and its label. */
    private static void found(Graphics2D g, Viewport v, Mark.Found found, Text text) {
        double h = Math.max(6, v.px(0.28));
        double cx = v.x(found.x());
        double cy = v.y(found.y());
        Path2D.Double diamond = new Path2D.Double();
        diamond.moveTo(cx, cy - h);
        diamond.lineTo(cx + h, cy);
        diamond.lineTo(cx, cy + h);
        diamond.lineTo(cx - h, cy);
        diamond.closePath();
        g.setColor(Palette.FOUND);
        g.fill(diamond);
        g.setColor(Palette.FOUND.darker().darker());
        g.setStroke(new BasicStroke(1.5f));
        g.draw(diamond);
        text.label(g, found.label(), cx + h + 3, cy + h + text.size(), Palette.FOUND.darker());
    }

    /** A red X of half-size {@code half} metres centred at (x, y). */
    private static void cross(Graphics2D g, Viewport v, double x, double y, double half) {
        double h = Math.max(5, v.px(half));
        double cx = v.x(x);
        double cy = v.y(y);
        g.setColor(Palette.MARK);
        g.setStroke(new BasicStroke((float) Math.max(2.5, h / 3.5), BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
        g.draw(new Line2D.Double(cx - h, cy - h, cx + h, cy + h));
        g.draw(new Line2D.Double(cx - h, cy + h, cx + h, cy - h));
    }

    private static Color blend(Color a, Color b, double t) {
        return new Color((int) (a.getRed() * (1 - t) + b.getRed() * t), (int) (a.getGreen() * (1 - t) + b.getGreen() * t),
                (int) (a.getBlue() * (1 - t) + b.getBlue() * t));
    }
}
