package net.smc.sim.arena;

/** Small plane-geometry helpers for arena checks (distances to rotated rectangles and circles). */
final class Geometry2 {
    private Geometry2() {
    }

    /**
     * Distance from (px, py) to a rectangle centred at (cx, cy) with half extents (hw, hh) turned
     * by {@code angle}; 0 inside it.
     */
    static double toRectangle(double px, double py, double cx, double cy, double hw, double hh, double angle) {
        double c = Math.cos(angle);
        double s = Math.sin(angle);
        double dx = px - cx;
        double dy = py - cy;
        double lx = Math.abs(c * dx + s * dy) - hw;
        double ly = Math.abs(-s * dx + c * dy) - hh;
        return Math.hypot(Math.max(lx, 0), Math.max(ly, 0));
    }

    /** Distance from (px, py) to a thick segment (a wall), 0 inside it. */
    static double toWall(double px, double py, double x1, double y1, double x2, double y2, double thickness) {
        double length = Math.hypot(x2 - x1, y2 - y1);
        return toRectangle(px, py, (x1 + x2) / 2, (y1 + y2) / 2, length / 2, thickness / 2, Math.atan2(y2 - y1, x2 - x1));
    }

    /** The distance from (px, py) to the nearest solid thing of {@code arena} (fence included). */
    static double clearance(Arena arena, double px, double py) {
        double nearest = Math.min(Math.min(px, arena.width() - px), Math.min(py, arena.height() - py));
        for (Arena.Wall w : arena.walls()) {
            nearest = Math.min(nearest, toWall(px, py, w.x1(), w.y1(), w.x2(), w.y2(), w.thickness()));
        }
        for (Arena.Door d : arena.doors()) {
            if (!d.open()) {
                nearest = Math.min(nearest, toWall(px, py, d.x1(), d.y1(), d.x2(), d.y2(), d.thickness()));
            }
        }
        for (Arena.Box b : arena.boxes()) {
            nearest = Math.min(nearest, toRectangle(px, py, b.x(), b.y(), b.width() / 2, b.height() / 2, b.angle()));
        }
        for (Arena.Cylinder c : arena.cylinders()) {
            nearest = Math.min(nearest, Math.hypot(px - c.x(), py - c.y()) - c.radius());
        }
        for (Arena.Hazard h : arena.hazards()) {
            if (h.radius() > 0) {
                nearest = Math.min(nearest, Math.hypot(px - h.x(), py - h.y()) - h.radius());
            }
        }
        for (Arena.Target t : arena.targets()) {
            nearest = Math.min(nearest, Math.hypot(px - t.x(), py - t.y()) - t.radius());
        }
        return nearest;
    }
}
