package net.smc.core.comm;

import java.util.HashMap;
import java.util.Map;

import net.smc.core.transport.Address;

/**
 * The first retransmission timeout of each peer, estimated from measured round trips in the way
 * of RFC 6298: a smoothed round trip {@code srtt} and its mean deviation {@code rttvar}, the
 * timeout {@code srtt + max(1 ms, 4 rttvar)} clamped to {@code [minTimeoutMillis,
 * initialTimeoutMillis]} of the {@link SenderSettings}.
 *
 * <ul>
 * <li>A first sample {@code r} sets {@code srtt = r}, {@code rttvar = r / 2}; each later one
 *     {@code rttvar = 3/4 rttvar + 1/4 |srtt - r|}, then {@code srtt = 7/8 srtt + 1/8 r}.</li>
 * <li>Samples come from the Acks of messages transmitted once (Karn's rule: the Ack of a
 *     retransmitted message may answer any copy, {@link MessageSender} offers none) and from
 *     replies that name the request they answer ({@link MessageSender#roundTrip}: a discovery
 *     reply names its discovery), so a peer can be measured before anything critical went to it.</li>
 * <li>A peer with no sample gets the cell's estimate: the same smoothing over every sample from
 *     every peer (as TCP stacks cache path metrics), whose variation also holds how the peers differ.
 *     Only when nothing was measured at all does the initial timeout apply.</li>
 * <li>A first try that times out doubles that peer's timeout (up to the initial timeout) until its
 *     next sample: a peer whose round trips grew past the estimate gives no samples (all its
 *     messages time out, and Karn's rule drops them), so it must not be retried at the stale rate.</li>
 * </ul>
 *
 * <p>One entry per peer measured; single-threaded, like its {@link MessageSender}.
 */
final class RttEstimator {
    /** The clock's granularity, the least variation term (RFC 6298's G). */
    private static final double GRANULARITY_MILLIS = 1.0;

    /** One smoothed round trip and its variation, and the timeout they give. */
    private static final class Estimate {
        double srtt;
        double rttvar;
        long timeoutMillis;

        void add(double r, long min, long max) {
            if (timeoutMillis == 0) {
                srtt = r;
                rttvar = r / 2;
            } else {
                rttvar = 0.75 * rttvar + 0.25 * Math.abs(srtt - r);
                srtt = 0.875 * srtt + 0.125 * r;
            }
            timeoutMillis = clamp((long) Math.ceil(srtt + Math.max(GRANULARITY_MILLIS, 4 * rttvar)), min, max);
        }
    }

    private final long minMillis;
    private final long maxMillis;
    private final Map<Address, Estimate> peers = new HashMap<>();
    /** Every sample of every peer: the estimate of a peer not measured yet. */
    private final Estimate cell = new Estimate();

    RttEstimator(SenderSettings settings) {
        this.minMillis = settings.minTimeoutMillis();
        this.maxMillis = settings.initialTimeoutMillis();
    }

    /** The first-try timeout for a message to {@code peer}: its own estimate, else the cell's, else the initial timeout. */
    long timeoutMillis(Address peer) {
        Estimate p = peers.get(peer);
        return p != null ? p.timeoutMillis : cellTimeoutMillis();
    }

    /** The cell's estimate over all its peers, or the initial timeout when nothing was measured. */
    long cellTimeoutMillis() {
        return cell.timeoutMillis == 0 ? maxMillis : cell.timeoutMillis;
    }

    /**
     * Records a round trip of {@code rttMillis} to {@code peer}.
     *
     * @throws IllegalArgumentException when it is negative
     */
    void sample(Address peer, long rttMillis) {
        if (rttMillis < 0) {
            throw new IllegalArgumentException("round trip of " + rttMillis + " ms to " + peer
                    + " is negative; the clock must not run backwards");
        }
        peers.computeIfAbsent(peer, p -> new Estimate()).add(rttMillis, minMillis, maxMillis);
        cell.add(rttMillis, minMillis, maxMillis);
    }

    /** A first try to {@code peer} timed out: its timeout doubles, up to the initial timeout, until its next sample. */
    void timedOut(Address peer) {
        Estimate p = peers.get(peer);
        if (p != null) {
            p.timeoutMillis = clamp(2 * p.timeoutMillis, minMillis, maxMillis);
        }
    }

    /** The smoothed round trip to {@code peer}, NaN without a sample (for tests and diagnostics). */
    double smoothedRttMillis(Address peer) {
        Estimate p = peers.get(peer);
        return p == null ? Double.NaN : p.srtt;
    }

    /** The round-trip variation of {@code peer}, NaN without a sample (for tests and diagnostics). */
    double rttVariationMillis(Address peer) {
        Estimate p = peers.get(peer);
        return p == null ? Double.NaN : p.rttvar;
    }

    /** Peers with an estimate of their own. */
    int peers() {
        return peers.size();
    }

    private static long clamp(long millis, long min, long max) {
        return Math.max(min, Math.min(max, millis));
    }
}
