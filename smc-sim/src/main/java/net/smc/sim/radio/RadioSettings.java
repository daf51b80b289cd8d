package net.smc.sim.radio;

/**
 * How radio links behave in the world. A link's quality is
 * {@code (1 - (d / range)^4) * wallFactor^walls} for two radios {@code d} metres apart with
 * {@code walls} walls or closed doors between them, and 0 beyond {@code range} or below
 * {@code minQuality}. A datagram gets through with probability equal to the quality, so loss
 * rises with distance and with every wall crossed.
 *
 * @param range          the longest link in the open, m
 * @param wallFactor     the quality kept through each wall, 0..1
 * @param minQuality     below this quality there is no link, 0..1
 * @param unboundReaches whether a node the world does not know (no robot or station bound to its
 *                       address: a wired command base, say) reaches and is reached by everyone
 */
public record RadioSettings(double range, double wallFactor, double minQuality, boolean unboundReaches) {

    public RadioSettings {
        if (!(range > 0) || Double.isInfinite(range)) {
            throw new IllegalArgumentException("radio range " + range + " m is not a positive finite number; it must be");
        }
        if (!(wallFactor >= 0 && wallFactor <= 1)) {
            throw new IllegalArgumentException("wallFactor " + wallFactor + " is out of range; it must be 0 to 1");
        }
        if (!(minQuality >= 0 && minQuality < 1)) {
            throw new IllegalArgumentException("minQuality " + minQuality + " is out of range; it must be 0 or more and below 1");
        }
    }

    /**
     * An ad-hoc 802.11 network of small laptops such as the demonstration's Asus EEE PCs, scaled
     * to the arenas: 30 m in the open, a wall keeps 40% of the quality, no link under 10%.
     */
    public static RadioSettings defaults() {
        return new RadioSettings(30, 0.4, 0.1, true);
    }
}
