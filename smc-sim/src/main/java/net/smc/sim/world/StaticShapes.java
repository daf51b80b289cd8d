package net.smc.sim.world;

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
    private int rectCount;
    private int circleCount;

    StaticShapes(Arena arena) {
        int nRects = 4 + arena.walls().size() + arena.doors().size() + arena.boxes().size();
        rects = new double[7 * nRects];
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

    /** How many radio-blocking rectangles (fence, walls, closed doors) the segment from a to b touches. */
    int wallsCrossed(double ax, double ay, double bx, double by) {
        int n = 0;
        for (int r = 0; r < rectCount; r++) {
            if (rects[7 * r + 6] != 0 && crossesRect(7 * r, ax, ay, bx, by)) {
                n++;
            }
        }
        return n;
    }

    private boolean crossesRect(int i, double ax, double ay, double bx, double by) {
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
        double[] range = {0, 1};
        return slab(lpx, ldx, rects[i + 2], range) && slab(lpy, ldy, rects[i + 3], range);
    }

    /** Narrows {@code range} (of the segment's parameter) to where it is within [-half, half] on one axis. */
    private static boolean slab(double p, double d, double half, double[] range) {
        if (Math.abs(d) < 1e-12) {
            return Math.abs(p) <= half;
        }
        double t1 = (-half - p) / d;
        double t2 = (half - p) / d;
        range[0] = Math.max(range[0], Math.min(t1, t2));
        range[1] = Math.min(range[1], Math.max(t1, t2));
        return range[0] <= range[1];
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
