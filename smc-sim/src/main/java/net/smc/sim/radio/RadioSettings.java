package net.smc.sim.radio;

/**
 * How radio links behave in the world. A link's quality is
 * {@code (1 - (d / range)^4) * wallFactor^walls} for two radios {@code d} metres apart with
 * {@code walls} walls or closed doors between them, and 0 beyond {@code range} or below
 * {@code minQuality}. A datagram gets through with probability equal to the quality, so loss
 * rises with distance and with every wall crossed.
 *
 * <p>Positions are read every {@code refreshMillis} of mission time, not every world step: a
 * link's quality is that of the positions at the last refresh, and holds until the next (a Koala
 * moves at most 4 cm in the default 100 ms, and links between still robots do not change). A
 * robot whose radio is switched off (a disabled robot) falls silent at once, not at the refresh.
 *
 * @param range          the longest link in the open, m
 * @param wallFactor     the quality kept through each wall, 0..1
 * @param minQuality     below this quality there is no link, 0..1
 * @param unboundReaches whether a node the world does not know (no robot or station bound to its
 *                       address: a wired command base, say) reaches and is reached by everyone
 * @param refreshMillis  how often, in mission time, the links are computed afresh from the
 *                       positions, 1 to 60,000 ms; rounded to whole world steps, at least one
 */
public record RadioSettings(double range, double wallFactor, double minQuality, boolean unboundReaches,
                            int refreshMillis) {

    /** The default refresh of links, ms of mission time: five steps of 20 ms. */
    public static final int DEFAULT_REFRESH_MILLIS = 100;

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
        if (refreshMillis < 1 || refreshMillis > 60_000) {
            throw new IllegalArgumentException("radio refreshMillis " + refreshMillis + " is out of range; it must be 1 to 60000 ms");
        }
    }

    /** Settings with links refreshed every {@link #DEFAULT_REFRESH_MILLIS}. */
    public RadioSettings(double range, double wallFactor, double minQuality, boolean unboundReaches) {
        this(range, wallFactor, minQuality, unboundReaches, DEFAULT_REFRESH_MILLIS);
    }

    /** These settings with links refreshed every {@code millis} of mission time. */
    public RadioSettings withRefreshMillis(int millis) {
        return new RadioSettings(range, wallFactor, minQuality, unboundReaches, millis);
    }

    /**
     * An ad-hoc 802.11 network of small laptops such as the demonstration's Asus EEE PCs, scaled
     * to the arenas: 30 m in the open, a wall keeps 40% of the quality, no link under 10%, links
     * refreshed every 100 ms.
     */
    public static RadioSettings defaults() {
        return new RadioSettings(30, 0.4, 0.1, true);
    }
}
