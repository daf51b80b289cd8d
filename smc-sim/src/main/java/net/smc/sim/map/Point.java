package net.smc.sim.map;

/** A point on the plane, metres. */
public record Point(double x, double y) {

    public Point {
        if (!Double.isFinite(x) || !Double.isFinite(y)) {
            throw new IllegalArgumentException("point (" + x + ", " + y + ") must have finite coordinates");
        }
    }

    public double distanceTo(double px, double py) {
        return Math.hypot(px - x, py - y);
    }

    public double distanceTo(Point p) {
        return distanceTo(p.x, p.y);
    }
}
