package net.smc.scenario.netns;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ThreadLocalRandom;

/**
 * Whether this machine can hold a lab, found out by trying, and the one thing the lab installs for
 * itself: nftables, for packet loss. Both are settled once per JVM: the machine does not change
 * under a test run, and a failed install is not worth repeating.
 */
final class Availability {
    private static final Duration APT_TIMEOUT = Duration.ofSeconds(180);

    private static Optional<String> labReason;
    private static Optional<String> nftInstall;

    private Availability() {
    }

    /** Why no lab can be made here; see {@link NetnsLab#unavailableReason()}. */
    static synchronized Optional<String> labReason() {
        if (labReason == null) {
            labReason = probe();
        }
        return labReason;
    }

    /** Installs nftables unless nft is here or was tried already; empty when nft is here afterwards, otherwise why not. */
    static synchronized Optional<String> ensureNft() {
        if (LossTool.NFT.unavailableReason().isEmpty()) {
            return Optional.empty();
        }
        if (nftInstall == null) {
            nftInstall = installNftables();
        }
        return nftInstall;
    }

    private static Optional<String> probe() {
        if (!System.getProperty("os.name", "").startsWith("Linux")) {
            return Optional.of("network namespaces need Linux; this is " + System.getProperty("os.name"));
        }
        try {
            long uid = effectiveUid();
            if (uid != 0) {
                return Optional.of("network namespaces need root; this process runs as uid " + uid);
            }
        } catch (IOException e) {
            return Optional.of("cannot tell whether this process is root: " + e.getMessage());
        }
        Optional<Path> ip = Exec.find("ip");
        if (ip.isEmpty()) {
            return Optional.of("the ip command is not installed (Debian package iproute2)");
        }
        String probe = "smcprobe-" + ProcessHandle.current().pid() + "-"
                + String.format("%04x", ThreadLocalRandom.current().nextInt(0x10000));
        String tool = ip.get().toString();
        try {
            Exec.Result add = Exec.run(List.of(tool, "netns", "add", probe));
            if (!add.ok()) {
                return Optional.of("namespaces cannot be made here: " + add.failure());
            }
            try {
                Exec.Result links = Exec.run(List.of(tool, "-n", probe, "-batch", "-"),
                        "link add br0 type bridge\nlink add v0 type veth peer name v1\n", Map.of(), Exec.TIMEOUT);
                if (!links.ok()) {
                    return Optional.of("bridges or veth pairs cannot be made here: " + links.failure());
                }
            } finally {
                Exec.run(List.of(tool, "netns", "delete", probe));
            }
        } catch (IOException e) {
            return Optional.of("probing network namespaces failed: " + e.getMessage());
        }
        return Optional.empty();
    }

    /** The effective user id of this process, from {@code /proc/self/status}. */
    private static long effectiveUid() throws IOException {
        for (String line : Files.readAllLines(Path.of("/proc/self/status"))) {
            if (line.startsWith("Uid:")) {
                return Long.parseLong(line.substring(4).strip().split("\\s+")[1]);
            }
        }
        throw new IOException("/proc/self/status has no Uid: line");
    }

    /** {@code apt-get install nftables}, with an {@code apt-get update} first only when the plain install fails. */
    private static Optional<String> installNftables() {
        String missing = LossTool.NFT.unavailableReason().orElseThrow();
        try {
            if (effectiveUid() != 0) {
                return Optional.of(missing + ", and only root can install it");
            }
        } catch (IOException e) {
            return Optional.of(missing + ": " + e.getMessage());
        }
        Optional<Path> apt = Exec.find("apt-get");
        if (apt.isEmpty()) {
            return Optional.of(missing + ", and there is no apt-get to install it");
        }
        Map<String, String> env = Map.of("DEBIAN_FRONTEND", "noninteractive");
        List<String> install = List.of(apt.get().toString(), "install", "-y", "-q", "-o", "DPkg::Lock::Timeout=120", "nftables");
        try {
            Exec.Result result = Exec.run(install, null, env, APT_TIMEOUT);
            if (!result.ok()) {
                Exec.Result update = Exec.run(List.of(apt.get().toString(), "update", "-q"), null, env, APT_TIMEOUT);
                result = update.ok() ? Exec.run(install, null, env, APT_TIMEOUT) : update;
            }
            if (!result.ok()) {
                return Optional.of(missing + ", and installing it failed: " + tail(result.failure()));
            }
        } catch (IOException e) {
            return Optional.of(missing + ", and installing it failed: " + e.getMessage());
        }
        return LossTool.NFT.unavailableReason().map(reason -> reason + " even after apt-get installed nftables");
    }

    /** The last lines of a long message, on one line. */
    private static String tail(String text) {
        String[] lines = text.strip().split("\n");
        return String.join(" | ", List.of(lines).subList(Math.max(0, lines.length - 5), lines.length));
    }
}
