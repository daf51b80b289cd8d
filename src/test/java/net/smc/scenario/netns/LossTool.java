package net.smc.scenario.netns;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;

/**
 * How the lab drops a share of the packets that arrive at a host: a rule on the input hook of the
 * host's own namespace, so only that host's incoming traffic suffers (ARP is not IP and passes).
 * The kernel has no {@code netem} here, so delay and jitter are not emulated; loss is.
 *
 * <p>nftables is preferred; iptables' {@code statistic} match (on Debian, iptables-nft, which turns
 * it into an nftables {@code meta random} rule) does the same and is used when only it is installed.
 * Each tool owns its rules in the host's namespace outright: setting a loss replaces the previous
 * one, clearing removes it.
 */
enum LossTool {
    /** {@code numgen random mod 100 < P drop} in a table of its own ({@value #NFT_TABLE}). */
    NFT("nft", "nftables") {
        @Override
        void set(Path ip, String namespace, int percent) throws IOException {
            String script = resetScript()
                    + "table inet " + NFT_TABLE + " {\n"
                    + "  chain input {\n"
                    + "    type filter hook input priority -10; policy accept;\n"
                    + "    numgen random mod 100 < " + percent + " drop\n"
                    + "  }\n"
                    + "}\n";
            Exec.check(command(ip, namespace, "-f", "/dev/stdin"), script);
        }

        @Override
        void clear(Path ip, String namespace) throws IOException {
            Exec.check(command(ip, namespace, "-f", "/dev/stdin"), resetScript());
        }

        /** Makes the table if missing, then deletes it: one transaction that never fails for "no such table". */
        private String resetScript() {
            return "table inet " + NFT_TABLE + "\ndelete table inet " + NFT_TABLE + "\n";
        }
    },
    /** {@code -m statistic --mode random --probability P -j DROP} in the INPUT chain of the filter table. */
    IPTABLES("iptables", "iptables") {
        @Override
        void set(Path ip, String namespace, int percent) throws IOException {
            clear(ip, namespace);
            String probability = String.format(Locale.ROOT, "%.2f", percent / 100.0);
            Exec.check(command(ip, namespace, "-w", "-A", "INPUT", "-m", "statistic", "--mode", "random",
                    "--probability", probability, "-j", "DROP"));
        }

        @Override
        void clear(Path ip, String namespace) throws IOException {
            Exec.check(command(ip, namespace, "-w", "-F", "INPUT"));
        }
    };

    /** The nftables table the lab's loss rule lives in. */
    static final String NFT_TABLE = "smc_lab_loss";

    private final String executable;
    private final String debianPackage;

    LossTool(String executable, String debianPackage) {
        this.executable = executable;
        this.debianPackage = debianPackage;
    }

    /** Drops {@code percent} of the packets arriving in {@code namespace}, replacing any earlier loss. */
    abstract void set(Path ip, String namespace, int percent) throws IOException;

    /** Drops nothing any more in {@code namespace}. */
    abstract void clear(Path ip, String namespace) throws IOException;

    /** The command that provides this tool. */
    String executable() {
        return executable;
    }

    /** The Debian package that installs it. */
    String debianPackage() {
        return debianPackage;
    }

    /** Why this tool cannot be used here, if it cannot. */
    Optional<String> unavailableReason() {
        return Exec.find(executable).isPresent() ? Optional.empty()
                : Optional.of(executable + " is not installed (Debian package " + debianPackage + ")");
    }

    /** The first tool that is installed, nftables first. */
    static Optional<LossTool> preferred() {
        for (LossTool tool : values()) {
            if (tool.unavailableReason().isEmpty()) {
                return Optional.of(tool);
            }
        }
        return Optional.empty();
    }

    /** {@code ip netns exec NAMESPACE TOOL args...}. */
    List<String> command(Path ip, String namespace, String... args) {
        List<String> command = new ArrayList<>(List.of(ip.toString(), "netns", "exec", namespace,
                Exec.find(executable).map(Path::toString).orElse(executable)));
        command.addAll(List.of(args));
        return command;
    }
}
