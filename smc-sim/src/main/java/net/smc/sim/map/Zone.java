package net.smc.sim.map;

/**
 * A circular zone a robot must stay out of (a hazard, say).
 *
 * @param x      centre, metres
 * @param y      centre, metres
 * @param radius metres, positive
 */
public record Zone(double x, double y, double radius) {

    public Zone {
        if (!Double.isFinite(x) || !Double.isFinite(y)) {
            throw new IllegalArgumentException("zone centre (" + x + ", " + y + ") must be finite");
        }
        if (!(radius > 0) || !Double.isFinite(radius)) {
            throw new IllegalArgumentException("zone radius " + radius + " must be a positive finite number of metres");
        }
    }

    /** Whether {@code (px, py)} lies within the zone grown by {@code margin}. */
    public boolean contains(double px, double py, double margin) {
        return Math.hypot(px - x, py - y) <= radius + margin;
    }
}
