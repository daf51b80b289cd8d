package net.smc.sim.render;

import java.awt.BasicStroke;
import java.awt.Graphics2D;
import java.awt.geom.AffineTransform;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Line2D;
import java.awt.geom.Rectangle2D;

import net.smc.sim.arena.Arena;

/** Draws the still part of a world: floor, metre grid, fence, walls, doors, obstacles, hazards, targets, stations. */
final class ArenaLayer {
    private ArenaLayer() {
    }

    static void paint(Graphics2D g, Arena arena, Viewport v, Text text) {
        Rectangle2D floor = new Rectangle2D.Double(v.x(0), v.y(arena.height()), v.px(arena.width()), v.px(arena.height()));
        g.setColor(Palette.FLOOR);
        g.fill(floor);
        g.setColor(Palette.GRID);
        g.setStroke(new BasicStroke(1f));
        for (int i = 1; i < arena.width(); i++) {
            g.draw(new Line2D.Double(v.x(i), v.y(0), v.x(i), v.y(arena.height())));
        }
        for (int j = 1; j < arena.height(); j++) {
            g.draw(new Line2D.Double(v.x(0), v.y(j), v.x(arena.width()), v.y(j)));
        }
        g.setColor(Palette.WALL);
        g.setStroke(new BasicStroke((float) Math.max(2, v.px(0.1))));
        g.draw(floor);
        for (Arena.Wall w : arena.walls()) {
            segment(g, v, w.x1(), w.y1(), w.x2(), w.y2(), w.thickness());
        }
        for (Arena.Door d : arena.doors()) {
            if (d.open()) {
                g.setColor(Palette.DOOR_OPEN);
                float dash = (float) Math.max(3, v.px(0.1));
                g.setStroke(new BasicStroke((float) Math.max(1.5, v.px(0.03)), BasicStroke.CAP_BUTT,
                        BasicStroke.JOIN_MITER, 10f, new float[] {dash, dash}, 0f));
                g.draw(new Line2D.Double(v.x(d.x1()), v.y(d.y1()), v.x(d.x2()), v.y(d.y2())));
            } else {
                g.setColor(Palette.DOOR_CLOSED);
                segment(g, v, d.x1(), d.y1(), d.x2(), d.y2(), d.thickness());
            }
        }
        g.setColor(Palette.OBSTACLE);
        for (Arena.Box b : arena.boxes()) {
            AffineTransform at = new AffineTransform();
            at.translate(v.x(b.x()), v.y(b.y()));
            at.rotate(-b.angle());
            g.fill(at.createTransformedShape(new Rectangle2D.Double(-v.px(b.width()) / 2, -v.px(b.height()) / 2,
                    v.px(b.width()), v.px(b.height()))));
        }
        for (Arena.Cylinder c : arena.cylinders()) {
            g.fill(disc(v, c.x(), c.y(), v.px(c.radius())));
        }
        for (Arena.Hazard h : arena.hazards()) {
            hazard(g, v, h, text);
        }
        for (Arena.Target t : arena.targets()) {
            target(g, v, t, text);
        }
        for (Arena.Station s : arena.stations()) {
            double r = Math.max(3, v.px(0.08));
            g.setColor(Palette.STATION);
            g.fill(new Rectangle2D.Double(v.x(s.x()) - r, v.y(s.y()) - r, 2 * r, 2 * r));
            text.label(g, s.id(), v.x(s.x()) + r + 2, v.y(s.y()) - r, Palette.STATION);
        }
    }

    /** The reach of a hazard as a translucent ring, its body as a yellow disc (at least 4 px across). */
    private static void hazard(Graphics2D g, Viewport v, Arena.Hazard h, Text text) {
        double reach = v.px(h.effect());
        g.setColor(Palette.HAZARD_REACH);
        g.fill(disc(v, h.x(), h.y(), reach));
        g.setColor(Palette.HAZARD_EDGE);
        g.setStroke(new BasicStroke(1.5f));
        g.draw(disc(v, h.x(), h.y(), reach));
        double body = Math.max(4, v.px(h.radius()));
        g.setColor(Palette.HAZARD);
        g.fill(disc(v, h.x(), h.y(), body));
        g.setColor(Palette.HAZARD_EDGE);
        g.draw(disc(v, h.x(), h.y(), body));
        text.label(g, h.id() + " (" + h.kind() + ")", v.x(h.x()) - reach * 0.7, v.y(h.y()) + reach + text.size(), Palette.HAZARD_EDGE);
    }

    /** A target: a green disc with a white cross (the wounded soldier). */
    private static void target(Graphics2D g, Viewport v, Arena.Target t, Text text) {
        double r = Math.max(5, v.px(t.radius()));
        double cx = v.x(t.x());
        double cy = v.y(t.y());
        g.setColor(Palette.SOLDIER);
        g.fill(disc(v, t.x(), t.y(), r));
        g.setColor(Palette.BACKGROUND);
        g.setStroke(new BasicStroke((float) Math.max(1.5, r / 3)));
        g.draw(new Line2D.Double(cx - r * 0.55, cy, cx + r * 0.55, cy));
        g.draw(new Line2D.Double(cx, cy - r * 0.55, cx, cy + r * 0.55));
        text.label(g, t.id(), cx - r, cy + r + text.size() + 2, Palette.SOLDIER);
    }

    private static void segment(Graphics2D g, Viewport v, double x1, double y1, double x2, double y2, double thickness) {
        g.setStroke(new BasicStroke((float) Math.max(2, v.px(thickness)), BasicStroke.CAP_SQUARE, BasicStroke.JOIN_MITER));
        g.draw(new Line2D.Double(v.x(x1), v.y(y1), v.x(x2), v.y(y2)));
    }

    static Ellipse2D disc(Viewport v, double x, double y, double radiusPx) {
        return new Ellipse2D.Double(v.x(x) - radiusPx, v.y(y) - radiusPx, 2 * radiusPx, 2 * radiusPx);
    }
}
