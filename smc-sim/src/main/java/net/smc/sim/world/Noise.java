package net.smc.sim.world;

/**
 * The world's seeded noise, counter-based: each draw is a pure function of the seed, a stream (a
 * robot), a counter (the step) and a channel (which sensor). So a sensor read twice in one step
 * reads the same, an observer that reads sensors does not change the run, and one seed replays
 * a run exactly whoever reads what.
 */
public final class Noise {
    private final long seed;

    public Noise(long seed) {
        this.seed = mix(seed ^ 0x5DEECE66DL);
    }

    /** A uniform draw in [0, 1). */
    public double uniform(long stream, long counter, int channel) {
        long bits = mix(seed + mix(stream * 0x9E3779B97F4A7C15L + mix(counter * 0xC2B2AE3D27D4EB4FL + channel)));
        return (bits >>> 11) * 0x1.0p-53;
    }

    /** A standard normal draw (Box-Muller over two uniform draws). */
    public double gaussian(long stream, long counter, int channel) {
        double u1 = uniform(stream, counter, 2 * channel);
        double u2 = uniform(stream, counter, 2 * channel + 1);
        return Math.sqrt(-2 * Math.log1p(-u1)) * Math.cos(2 * Math.PI * u2);
    }

    /** The SplitMix64 finaliser: a bijection that scatters nearby inputs. */
    static long mix(long z) {
        z = (z ^ (z >>> 30)) * 0xBF58476D1CE4E5B9L;
        z = (z ^ (z >>> 27)) * 0x94D049BB133111EBL;
        return z ^ (z >>> 31);
    }
}
