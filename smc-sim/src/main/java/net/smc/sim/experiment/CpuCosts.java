package net.smc.sim.experiment;

import java.io.IOException;
import java.io.Reader;
import java.io.Writer;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.Properties;
import java.util.function.Consumer;

/**
 * What each operation of a cell costs its CPU, in nanoseconds, as {@link Calibration} measured it
 * for this engine on this machine. Saved with every experiment's results and readable back, so a
 * run replays exactly with the costs it was run with. A file written before the compression of
 * policy texts lacks its two costs; {@link #load} gives them their defaults and says so.
 *
 * @param signNanos           an Ed25519 signature (a {@code SIGNED} datagram: discovery, first contact)
 * @param verifyNanos         an Ed25519 verification (a signed datagram, or a credential on first contact)
 * @param agreeNanos          an X25519 key agreement (a pair session's key, on first contact)
 * @param macNanos            HMAC-SHA256 of one datagram: the fixed part
 * @param macNanosPerByte     HMAC-SHA256: per byte
 * @param codecNanos          encoding or decoding one message: the fixed part
 * @param codecNanosPerByte   encoding or decoding: per byte
 * @param loadNanosPerByte    parsing and running a policy file (creating its policies), per byte of text
 * @param conditionNanos      offering an event to one obligation policy whose condition is false
 * @param deflateNanosPerByte deflating a policy text to send, per byte of text
 * @param inflateNanosPerByte inflating a policy text received deflated, per byte of text
 */
public record CpuCosts(double signNanos, double verifyNanos, double agreeNanos, double macNanos, double macNanosPerByte,
                       double codecNanos, double codecNanosPerByte, double loadNanosPerByte, double conditionNanos,
                       double deflateNanosPerByte, double inflateNanosPerByte) {

    /** No cost at all: the network alone decides the set-up time. */
    public static final CpuCosts ZERO = new CpuCosts(0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0);

    /**
     * The deflating cost given to a costs file without one, so that such a file (the README's
     * {@code docs/fig8-costs.properties}) replays the same on any machine. {@link Calibration} gave
     * 16 to 43 ns/B on the project's build VM under a load of 6 to 7 (three calibrations); the
     * default takes the upper end, as that file's other costs were measured slower than today's
     * (its codec 8.6 ns/B against 3 to 11).
     */
    public static final double DEFAULT_DEFLATE_NANOS_PER_BYTE = 40.0;
    /** The inflating cost given to a costs file without one: 4 to 13 ns/B measured as {@link #DEFAULT_DEFLATE_NANOS_PER_BYTE} was. */
    public static final double DEFAULT_INFLATE_NANOS_PER_BYTE = 10.0;

    public CpuCosts {
        double[] all = {signNanos, verifyNanos, agreeNanos, macNanos, macNanosPerByte, codecNanos, codecNanosPerByte,
            loadNanosPerByte, conditionNanos, deflateNanosPerByte, inflateNanosPerByte};
        for (double v : all) {
            if (!(v >= 0) || Double.isInfinite(v)) {
                throw new IllegalArgumentException("a CPU cost of " + v + " ns is not valid; each must be a finite 0 or more");
            }
        }
    }

    /** Multiplies every cost by {@code factor} (e.g. for a slower vehicle CPU than the machine measured on). */
    public CpuCosts scaled(double factor) {
        if (!(factor > 0)) {
            throw new IllegalArgumentException("CPU scale factor " + factor + " must be above 0");
        }
        return new CpuCosts(signNanos * factor, verifyNanos * factor, agreeNanos * factor, macNanos * factor,
                macNanosPerByte * factor, codecNanos * factor, codecNanosPerByte * factor, loadNanosPerByte * factor,
                conditionNanos * factor, deflateNanosPerByte * factor, inflateNanosPerByte * factor);
    }

    public void save(Path file) throws IOException {
        Properties p = new Properties();
        p.setProperty("signNanos", fmt(signNanos));
        p.setProperty("verifyNanos", fmt(verifyNanos));
        p.setProperty("agreeNanos", fmt(agreeNanos));
        p.setProperty("macNanos", fmt(macNanos));
        p.setProperty("macNanosPerByte", fmt(macNanosPerByte));
        p.setProperty("codecNanos", fmt(codecNanos));
        p.setProperty("codecNanosPerByte", fmt(codecNanosPerByte));
        p.setProperty("loadNanosPerByte", fmt(loadNanosPerByte));
        p.setProperty("conditionNanos", fmt(conditionNanos));
        p.setProperty("deflateNanosPerByte", fmt(deflateNanosPerByte));
        p.setProperty("inflateNanosPerByte", fmt(inflateNanosPerByte));
        try (Writer w = Files.newBufferedWriter(file)) {
            p.store(w, "CPU cost per operation, ns (net.smc.sim.experiment.CpuCosts)");
        }
    }

    /** As {@link #load(Path, Consumer)}, saying nothing of defaulted costs. */
    public static CpuCosts load(Path file) throws IOException {
        return load(file, note -> { });
    }

    /**
     * Reads costs saved by {@link #save}; a missing or malformed entry is an error naming it, except
     * the two compression costs, which a file written before them lacks: each missing one is given
     * its default ({@link #DEFAULT_DEFLATE_NANOS_PER_BYTE}, {@link #DEFAULT_INFLATE_NANOS_PER_BYTE})
     * and {@code notes} is told which, in a line of its own.
     */
    public static CpuCosts load(Path file, Consumer<String> notes) throws IOException {
        Properties p = new Properties();
        try (Reader r = Files.newBufferedReader(file)) {
            p.load(r);
        }
        return new CpuCosts(get(p, file, "signNanos"), get(p, file, "verifyNanos"), get(p, file, "agreeNanos"),
                get(p, file, "macNanos"), get(p, file, "macNanosPerByte"), get(p, file, "codecNanos"),
                get(p, file, "codecNanosPerByte"), get(p, file, "loadNanosPerByte"), get(p, file, "conditionNanos"),
                getOr(p, file, "deflateNanosPerByte", DEFAULT_DEFLATE_NANOS_PER_BYTE, notes),
                getOr(p, file, "inflateNanosPerByte", DEFAULT_INFLATE_NANOS_PER_BYTE, notes));
    }

    private static double getOr(Properties p, Path file, String key, double fallback, Consumer<String> notes) {
        if (p.getProperty(key) == null) {
            notes.accept(file + " has no '" + key + "' (written before policy texts were compressed): "
                    + fmt(fallback) + " ns, the default");
            return fallback;
        }
        return get(p, file, key);
    }

    private static double get(Properties p, Path file, String key) {
        String v = p.getProperty(key);
        if (v == null) {
            throw new IllegalArgumentException(file + ": no '" + key + "'; a costs file lists every cost of CpuCosts");
        }
        try {
            return Double.parseDouble(v.trim());
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException(file + ": '" + key + "' is '" + v + "', not a number of nanoseconds");
        }
    }

    private static String fmt(double v) {
        return String.format(Locale.ROOT, "%.1f", v);
    }

    @Override
    public String toString() {
        return String.format(Locale.ROOT, "sign %.0f ns, verify %.0f ns, X25519 %.0f ns, HMAC %.0f ns + %.2f ns/B, "
                + "codec %.0f ns + %.2f ns/B, policy load %.0f ns/B, condition %.0f ns, deflate %.1f ns/B, inflate %.1f ns/B",
                signNanos, verifyNanos, agreeNanos, macNanos, macNanosPerByte, codecNanos, codecNanosPerByte, loadNanosPerByte,
                conditionNanos, deflateNanosPerByte, inflateNanosPerByte);
    }
}
