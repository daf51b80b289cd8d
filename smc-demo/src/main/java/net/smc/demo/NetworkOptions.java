package net.smc.demo;

import java.util.Locale;

import net.smc.sim.experiment.RadioNetwork;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;

/**
 * The simulated network of {@code smc experiment setup-time}: a model ({@code --network}) and the
 * figures that replace its own ({@code --hops}, {@code --hop-latency}, {@code --hop-jitter},
 * {@code --bandwidth}, {@code --loss}), checked into a {@link RadioNetwork}.
 */
final class NetworkOptions {
    /** The most radio hops, and the longest hop latency or jitter, the options take. */
    private static final int MAX_HOPS = 100;
    private static final long MAX_HOP_MILLIS = 60_000;

    @Option(names = "--network", paramLabel = "MODEL", defaultValue = "adhoc", description = {"The network model of "
            + "the simulated runs: 'adhoc' (an 802.11 ad-hoc radio network: 2 hops of 2 ms + up to 2 ms, 2.75 Mbit/s per "
            + "sender, 1%% loss) or 'lan' (one switched Ethernet, as the paper's testbed of Linux machines: 1 hop of up to "
            + "1 ms, 100 Mbit/s, no loss); the options below replace its figures (default: ${DEFAULT-VALUE})."})
    String network;

    @Option(names = "--hops", paramLabel = "N", description = "Radio hops between any two vehicles (default: "
            + "the model's: 2 adhoc, 1 lan).")
    Integer hops;

    @Option(names = "--hop-latency", paramLabel = "MS", description = "Base delay of one hop, ms (default: the model's: 2 "
            + "adhoc, 0 lan).")
    Long hopLatencyMillis;

    @Option(names = "--hop-jitter", paramLabel = "MS", description = "Largest extra delay of one hop, ms (default: the "
            + "model's: 2 adhoc, 1 lan).")
    Long hopJitterMillis;

    @Option(names = "--bandwidth", paramLabel = "MBIT", description = "Each sender's radio rate, Mbit/s (default: the "
            + "model's: 2.75 adhoc, 100 lan).")
    Double bandwidthMbit;

    @Option(names = "--loss", paramLabel = "P", description = "Chance that a datagram copy is lost, from 0 to below 1 "
            + "(default: the model's: 0.01 adhoc, 0 lan).")
    Double loss;

    /**
     * The network of the simulated runs: the model {@code --network} names
     * ({@link RadioNetwork#ADHOC_80211} or {@link RadioNetwork#SWITCHED_LAN}) with what the options
     * give in its place; a value out of range, or a model of another name, is a usage error of
     * {@code spec}'s command naming the option.
     */
    RadioNetwork radio(CommandSpec spec) {
        RadioNetwork model = switch (network.trim().toLowerCase(Locale.ROOT)) {
            case "adhoc" -> RadioNetwork.ADHOC_80211;
            case "lan" -> RadioNetwork.SWITCHED_LAN;
            default -> throw new ParameterException(spec.commandLine(), "--network '" + network
                    + "': it must be 'adhoc' or 'lan'");
        };
        if (hops != null && (hops < 1 || hops > MAX_HOPS)) {
            throw new ParameterException(spec.commandLine(), "--hops " + hops + ": it must be from 1 to " + MAX_HOPS);
        }
        checkHopMillis(spec, "--hop-latency", hopLatencyMillis);
        checkHopMillis(spec, "--hop-jitter", hopJitterMillis);
        if (bandwidthMbit != null && !(bandwidthMbit >= 1e-5 && bandwidthMbit <= 1e6)) {
            throw new ParameterException(spec.commandLine(), "--bandwidth " + bandwidthMbit
                    + ": it must be from 0.00001 to 1000000 Mbit/s");
        }
        if (loss != null && !(loss >= 0 && loss < 1)) {
            throw new ParameterException(spec.commandLine(), "--loss " + loss + ": it must be from 0 to below 1 (0.01 is 1%)");
        }
        return new RadioNetwork(hops == null ? model.hops() : hops,
                hopLatencyMillis == null ? model.hopLatencyMillis() : hopLatencyMillis,
                hopJitterMillis == null ? model.hopJitterMillis() : hopJitterMillis,
                bandwidthMbit == null ? model.bytesPerSecond() : Math.round(bandwidthMbit * 1e6 / 8),
                loss == null ? model.loss() : loss);
    }

    /** A hop's delay given as {@code option} must be from 0 to {@value #MAX_HOP_MILLIS} ms (null: not given). */
    private static void checkHopMillis(CommandSpec spec, String option, Long millis) {
        if (millis != null && (millis < 0 || millis > MAX_HOP_MILLIS)) {
            throw new ParameterException(spec.commandLine(), option + " " + millis + ": it must be from 0 to "
                    + MAX_HOP_MILLIS + " ms");
        }
    }
}
