package net.smc.sim.world;

import net.smc.sim.arena.Arena;

/**
 * The arena's solid shapes that never move (fence, walls, closed doors, boxes, cylinders), kept
 * apart from the physics world for the line tests that the camera's line of sight and the radio's
 * wall count make many times per step: an exact segment-against-rectangle (slab) and
 * segment-against-circle test, without the physics world's broad phase and its moving robots.
 * The shapes are the same as the static bodies' (walls' square ends included).
 */
final class StaticShapes {
    private static final double FENCE = 0.2;
    private final double[] rects;   // per rectangle: cx, cy, hw, hh, cos, sin, blocksRadio (0/1)
    private final double[] circles; // per circle: cx, cy, r
    private final double[] rectBoxes;   // per rectangle: its bounding box minX, minY, maxX, maxY
    private int rectCount;
    private final int blockingCount;   // the first rectangles, those that block the radio
    private int circleCount;

    StaticShapes(Arena arena) {
        int nRects = 4 + arena.walls().size() + arena.doors().size() + arena.boxes().size();
        rects = new double[7 * nRects];
        rectBoxes = new double[4 * nRects];
        circles = new double[3 * arena.cylinders().size()];
        double w = arena.width();
        double h = arena.height();
        rect(w / 2, -FENCE / 2, w / 2 + FENCE, FENCE / 2, 0, true);
        rect(w / 2, h + FENCE / 2, w / 2 + FENCE, FENCE / 2, 0, true);
        rect(-FENCE / 2, h / 2, FENCE / 2, h / 2, 0, true);
        rect(w + FENCE / 2, h / 2, FENCE / 2, h / 2, 0, true);
        for (Arena.Wall wall : arena.walls()) {
            segment(wall.x1(), wall.y1(), wall.x2(), wall.y2(), wall.thickness());
        }
        for (Arena.Door door : arena.doors()) {
            if (!door.open()) {
                segment(door.x1(), door.y1(), door.x2(), door.y2(), door.thickness());
            }
        }
        blockingCount = rectCount;
        for (Arena.Box box : arena.boxes()) {
            rect(box.x(), box.y(), box.width() / 2, box.height() / 2, box.angle(), false);
        }
        for (Arena.Cylinder c : arena.cylinders()) {
            circles[3 * circleCount] = c.x();
            circles[3 * circleCount + 1] = c.y();
            circles[3 * circleCount + 2] = c.radius();
            circleCount++;
        }
    }

    private void segment(double x1, double y1, double x2, double y2, double thickness) {
        rect((x1 + x2) / 2, (y1 + y2) / 2, (Math.hypot(x2 - x1, y2 - y1) + thickness) / 2, thickness / 2,
                Math.atan2(y2 - y1, x2 - x1), true);
    }

    private void rect(double cx, double cy, double hw, double hh, double angle, boolean blocksRadio) {
        // the bounding box, a hair wider so that rounding never rejects a segment the exact test accepts
        double ex = Math.abs(Math.cos(angle)) * hw + Math.abs(Math.sin(angle)) * hh + 1e-9;
        double ey = Math.abs(Math.sin(angle)) * hw + Math.abs(Math.cos(angle)) * hh + 1e-9;
        int b = 4 * rectCount;
        rectBoxes[b] = cx - ex;
        rectBoxes[b + 1] = cy - ey;
        rectBoxes[b + 2] = cx + ex;
        rectBoxes[b + 3] = cy + ey;
        int i = 7 * rectCount++;
        rects[i] = cx;
        rects[i + 1] = cy;
        rects[i + 2] = hw;
        rects[i + 3] = hh;
        rects[i + 4] = Math.cos(angle);
        rects[i + 5] = Math.sin(angle);
        rects[i + 6] = blocksRadio ? 1 : 0;
    }

    /** Whether the segment from a to b touches no shape. */
    boolean clear(double ax, double ay, double bx, double by) {
        for (int r = 0; r < rectCount; r++) {
            if (crossesRect(7 * r, ax, ay, bx, by)) {
                return false;
            }
        }
        for (int c = 0; c < circleCount; c++) {
            if (crossesCircle(3 * c, ax, ay, bx, by)) {
                return false;
            }
        }
        return true;
    }

    /**
     * How many radio-blocking rectangles (fence, walls, closed doors) the segment from a to b
     * touches, counting no further than {@code limit + 1}.
     */
    int wallsCrossed(double ax, double ay, double bx, double by, int limit) {
        int n = 0;
        for (int r = 0; r < blockingCount && n <= limit; r++) {
            if (crossesRect(7 * r, ax, ay, bx, by)) {
                n++;
            }
        }
        return n;
    }

    private boolean crossesRect(int i, double ax, double ay, double bx, double by) {
        int b = 4 * (i / 7);
        if (Math.max(ax, bx) < rectBoxes[b] || Math.min(ax, bx) > rectBoxes[b + 2]
                || Math.max(ay, by) < rectBoxes[b + 1] || Math.min(ay, by) > rectBoxes[b + 3]) {
            return false;   // the segment's bounding box misses the rectangle's, so the segment does too
        }
        // The segment's line misses the rectangle when the centre is further from it than the
        // rectangle reaches across it (lengths scaled by the segment's length; with a margin for rounding).
        double nx = ay - by;
        double ny = bx - ax;
        double ox = rects[i] - ax;
        double oy = rects[i + 1] - ay;
        double reach = rects[i + 2] * Math.abs(nx * rects[i + 4] + ny * rects[i + 5])
                + rects[i + 3] * Math.abs(ny * rects[i + 4] - nx * rects[i + 5]);
        double margin = 1e-9 * (Math.abs(nx) + Math.abs(ny)) * (1 + Math.abs(ox) + Math.abs(oy) + reach);
        if (Math.abs(nx * ox + ny * oy) > reach + margin) {
            return false;
        }
        double c = rects[i + 4];
        double s = rects[i + 5];
        double px = ax - rects[i];
        double py = ay - rects[i + 1];
        double dx = bx - ax;
        double dy = by - ay;
        double lpx = c * px + s * py;
        double lpy = -s * px + c * py;
        double ldx = c * dx + s * dy;
        double ldy = -s * dx + c * dy;
        // the slab test: narrow the segment's parameter range [lo, hi] to where it is within each axis's half extent
        double lo = 0;
        double hi = 1;
        double hw = rects[i + 2];
        if (Math.abs(ldx) < 1e-12) {
            if (Math.abs(lpx) > hw) {
                return false;
            }
        } else {
            double t1 = (-hw - lpx) / ldx;
            double t2 = (hw - lpx) / ldx;
            lo = Math.max(lo, Math.min(t1, t2));
            hi = Math.min(hi, Math.max(t1, t2));
            if (lo > hi) {
                return false;
            }
        }
        double hh = rects[i + 3];
        if (Math.abs(ldy) < 1e-12) {
            return Math.abs(lpy) <= hh;
        }
        double t1 = (-hh - lpy) / ldy;
        double t2 = (hh - lpy) / ldy;
        lo = Math.max(lo, Math.min(t1, t2));
        hi = Math.min(hi, Math.max(t1, t2));
        return lo <= hi;
    }

    private boolean crossesCircle(int i, double ax, double ay, double bx, double by) {
        double dx = bx - ax;
        double dy = by - ay;
        double fx = circles[i] - ax;
        double fy = circles[i + 1] - ay;
        double len2 = dx * dx + dy * dy;
        double t = len2 == 0 ? 0 : Math.max(0, Math.min(1, (fx * dx + fy * dy) / len2));
        double ex = ax + t * dx - circles[i];
        double ey = ay + t * dy - circles[i + 1];
        return ex * ex + ey * ey <= circles[i + 2] * circles[i + 2];
    }
}
