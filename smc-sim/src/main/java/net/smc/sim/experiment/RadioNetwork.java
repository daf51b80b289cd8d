package net.smc.sim.experiment;

import java.util.Locale;

import net.smc.core.transport.sim.LinkProfile;

/**
 * The model of an ad-hoc radio network the set-up time is measured on: every vehicle reaches every
 * other in {@code hops} radio hops, each adding {@code hopLatencyMillis} (medium access, forwarding
 * and propagation) plus up to {@code hopJitterMillis}; each sender's radio sends
 * {@code bytesPerSecond} (a datagram waits for the ones before it); a datagram copy is lost with
 * {@code loss} (after the link layer's own retries; the protocols retransmit what matters).
 *
 * <p>{@link #ADHOC_80211}, the default: 2 hops of 2 ms + up to 2 ms each, 1% loss, and 2.75 Mbit/s
 * per sender. These are assumed figures, not measured here: 802.11b (11 Mbit/s nominal) gives about
 * 5 to 6 Mbit/s of UDP throughput over one hop and about half of that over two (relaying shares the
 * channel); a few milliseconds per hop is the usual medium-access and forwarding delay of a lightly
 * loaded 802.11 ad-hoc network. The contention of many senders for the one shared channel is not
 * modelled (each sender's radio is independent), which favours schemes that send a lot at once.
 *
 * <p>{@link #SWITCHED_LAN}: a testbed of machines on one switched Ethernet, as the paper's experiment
 * ran on (generic Linux machines): one hop of up to 1 ms (a switch forwards in microseconds; the
 * simulated clock counts whole milliseconds, so a delay is 0 or 1 ms), 100 Mbit/s per sender, no
 * loss. Also assumed, not measured.
 *
 * @param hops             radio hops between any two vehicles, 1 or more
 * @param hopLatencyMillis base delay per hop, 0 or more
 * @param hopJitterMillis  largest extra delay per hop, 0 or more
 * @param bytesPerSecond   each sender's transmission rate, 1 or more
 * @param loss             chance that a datagram copy is lost, from 0 to 1
 */
public record RadioNetwork(int hops, long hopLatencyMillis, long hopJitterMillis, long bytesPerSecond, double loss) {
    public static final RadioNetwork ADHOC_80211 = new RadioNetwork(2, 2, 2, 343_750, 0.01);
    public static final RadioNetwork SWITCHED_LAN = new RadioNetwork(1, 0, 1, 12_500_000, 0);

    public RadioNetwork {
        if (hops < 1) {
            throw new IllegalArgumentException("hops " + hops + " must be 1 or more");
        }
        if (hopLatencyMillis < 0 || hopJitterMillis < 0) {
            throw new IllegalArgumentException("hop latency " + hopLatencyMillis + " ms and jitter " + hopJitterMillis
                    + " ms must be 0 or more");
        }
        if (bytesPerSecond < 1) {
            throw new IllegalArgumentException("bandwidth " + bytesPerSecond + " bytes/s must be 1 or more");
        }
        if (!(loss >= 0 && loss < 1)) {
            throw new IllegalArgumentException("loss " + loss + " must be from 0 to below 1");
        }
    }

    /** The link profile of every pair of vehicles. */
    public LinkProfile link() {
        return LinkProfile.DEFAULT.withLatency(hops * hopLatencyMillis, hops * hopJitterMillis)
                .withLoss(loss);
    }

    @Override
    public String toString() {
        return String.format(Locale.ROOT, "%d %s x (%d ms + up to %d ms), %.2f Mbit/s per sender, %.1f%% loss", hops,
                hops == 1 ? "hop" : "hops", hopLatencyMillis, hopJitterMillis, bytesPerSecond * 8 / 1e6, loss * 100);
    }
}
