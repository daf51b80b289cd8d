package net.smc.scenario.netns;

import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.concurrent.ThreadLocalRandom;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * A small network of hosts on one machine, for tests that run several {@code smc node} processes:
 * each host is a Linux network namespace with one address on a private subnet, and all hosts hang
 * on one bridge. A test can start processes on a host, cut a host off and heal it, and make a host
 * lose a share of its incoming packets.
 *
 * <pre>{@code
 * assumeTrue(NetnsLab.unavailableReason().isEmpty(), () -> NetnsLab.unavailableReason().get());
 * try (NetnsLab lab = NetnsLab.create("smcscn", 6)) {
 *     Process node = lab.start(0, List.of(smc, "node", ...), dir.resolve("node0.log"));
 *     lab.cut(3);  ...  lab.heal(3);
 *     lab.loss(2, 20);  ...  lab.clearLoss(2);
 *     node.destroyForcibly();   // SIGKILL one node
 * }                             // every process killed, every namespace gone
 * }</pre>
 *
 * <p>Layout: the bridge {@code br0} lives in a namespace of its own ({@code RUN-br}); host {@code i}
 * is the namespace {@code RUN-hI} whose {@code eth0} is a veth to the bridge port {@code hI} and has
 * the address {@code 10.77.0.(10+i)/24} (broadcast {@value #BROADCAST}). Every link is made inside the
 * lab's namespaces, so the machine's own network is never touched and interface names never
 * collide. {@code RUN} is {@code PREFIX-PID-XXXX} (the JVM's process id and 4 random hex digits):
 * labs of parallel runs never share a name, and a crashed run's leftovers are recognised by a process
 * id that is gone ({@link #cleanupStale}, which {@link #create} calls first).
 *
 * <p>Needs root and iproute2 ({@link #unavailableReason()}); loss needs nftables or iptables
 * ({@link #lossUnavailableReason()}, {@link #ensureLossTool()}). The kernel here has no
 * {@code netem}: there is no delay or jitter emulation. Not thread-safe: drive a lab from one thread.
 */
public final class NetnsLab implements AutoCloseable {
    /** The hosts' subnet. */
    public static final String SUBNET = "10.77.0.0/24";
    /** The subnet's broadcast address: a UDP datagram sent there reaches every host that is not cut. */
    public static final String BROADCAST = "10.77.0.255";
    /** The most hosts a lab can have: addresses .10 to .249. */
    public static final int MAX_HOSTS = 240;

    private static final String SUBNET_BASE = "10.77.0.";
    private static final int FIRST_HOST_OCTET = 10;
    private static final int PREFIX_BITS = 24;
    /** Lower case letters and digits, starting with a letter: safe in a file name, and free of the '-' that splits a run's name. */
    private static final Pattern PREFIX = Pattern.compile("[a-z][a-z0-9]{0,15}");
    private static final Duration LINK_UP_WAIT = Duration.ofSeconds(5);

    /** One host of a lab: its index, its namespace's name and its IPv4 address. */
    public record Host(int index, String namespace, String address) {
    }

    private final Path ip;
    private final String run;
    private final String bridgeNamespace;
    private final List<Host> hosts;
    /** Namespaces made so far, in order, so that a half-made lab is removed too. */
    private final List<String> namespaces = new ArrayList<>();
    private final List<Process> processes = new ArrayList<>();
    private final Map<Integer, LossTool> lossTools = new HashMap<>();
    private final Thread shutdownHook = new Thread(this::closeAtExit, "netns-lab-cleanup");
    private boolean closed;

    private NetnsLab(Path ip, String run, int hostCount) {
        this.ip = ip;
        this.run = run;
        this.bridgeNamespace = run + "-br";
        List<Host> list = new ArrayList<>();
        for (int i = 0; i < hostCount; i++) {
            list.add(new Host(i, run + "-h" + i, SUBNET_BASE + (FIRST_HOST_OCTET + i)));
        }
        this.hosts = List.copyOf(list);
    }

    /**
     * Makes a lab of {@code hosts} hosts, after removing what crashed runs with the same prefix left
     * behind. On failure, whatever was made is removed again.
     *
     * @param prefix a short name for the test: 1-16 lower case letters and digits, starting with a letter
     * @throws IllegalStateException when the lab cannot run here ({@link #unavailableReason()} says why)
     * @throws IOException           when a command fails (the message names it and its output)
     */
    public static NetnsLab create(String prefix, int hosts) throws IOException {
        checkPrefix(prefix);
        if (hosts < 1 || hosts > MAX_HOSTS) {
            throw new IllegalArgumentException("a lab of " + hosts + " hosts cannot be made; it must have 1 to "
                    + MAX_HOSTS + " (one address each in " + SUBNET + ")");
        }
        Optional<String> reason = unavailableReason();
        if (reason.isPresent()) {
            throw new IllegalStateException("a network namespace lab cannot run here: " + reason.get());
        }
        cleanupStale(prefix);
        String run = prefix + "-" + ProcessHandle.current().pid() + "-"
                + String.format("%04x", ThreadLocalRandom.current().nextInt(0x10000));
        NetnsLab lab = new NetnsLab(Exec.find("ip").orElseThrow(), run, hosts);
        Runtime.getRuntime().addShutdownHook(lab.shutdownHook);
        try {
            lab.build();
        } catch (IOException | RuntimeException e) {
            try {
                lab.close();
            } catch (RuntimeException cleanup) {
                e.addSuppressed(cleanup);
            }
            throw e;
        }
        return lab;
    }

    /**
     * Why a lab cannot be made on this machine: not Linux, not root, no {@code ip} command, or the
     * kernel refuses a namespace, a bridge or a veth pair (as in an unprivileged container). Empty
     * when it can. Checked once per JVM, by making and removing a probe namespace.
     */
    public static Optional<String> unavailableReason() {
        return Availability.labReason();
    }

    /**
     * Why {@link #loss} cannot work here: the lab itself cannot ({@link #unavailableReason()}), or
     * neither {@code nft} (Debian package nftables) nor {@code iptables} is installed. Empty when it can.
     */
    public static Optional<String> lossUnavailableReason() {
        Optional<String> lab = unavailableReason();
        if (lab.isPresent()) {
            return lab;
        }
        if (LossTool.preferred().isPresent()) {
            return Optional.empty();
        }
        return Optional.of(LossTool.NFT.unavailableReason().orElseThrow() + ", nor is "
                + LossTool.IPTABLES.unavailableReason().orElseThrow() + "; install one: apt-get install -y nftables");
    }

    /**
     * Makes sure {@code nft} is here, installing Debian's nftables package with apt-get when it is
     * missing and this process is root with apt-get (a few seconds; an {@code apt-get update} first
     * only when the plain install fails). Tried once per JVM. A side effect on the machine, meant for
     * the disposable root machines tests run on.
     *
     * @return why loss cannot work here even so ({@link #lossUnavailableReason()}, with the install's
     *         failure when it was tried), empty when it can
     */
    public static Optional<String> ensureLossTool() {
        if (unavailableReason().isPresent()) {
            return unavailableReason();
        }
        Optional<String> nft = Availability.ensureNft();
        return nft.isPresent() && LossTool.preferred().isEmpty() ? nft : Optional.empty();
    }

    /** The unique name of this lab's run, {@code PREFIX-PID-XXXX}: every namespace it makes starts with it. */
    public String run() {
        return run;
    }

    /** How many hosts the lab has. */
    public int hosts() {
        return hosts.size();
    }

    /**
     * Host {@code index}: its namespace and address.
     *
     * @throws IndexOutOfBoundsException naming the index and the range when there is no such host
     */
    public Host host(int index) {
        checkHost(index);
        return hosts.get(index);
    }

    /** The namespace that holds the bridge. */
    public String bridgeNamespace() {
        return bridgeNamespace;
    }

    /** The subnet's broadcast address, {@value #BROADCAST}. */
    public String broadcastAddress() {
        return BROADCAST;
    }

    /**
     * Starts {@code command} inside host {@code host}'s namespace ({@code ip netns exec NS command...}),
     * with stdin empty and stdout and stderr together in {@code log} (made, or emptied). The process
     * is the lab's to kill at {@link #close()}; a test may kill it earlier ({@code destroyForcibly()}
     * sends SIGKILL).
     */
    public Process start(int host, List<String> command, Path log) throws IOException {
        checkOpen();
        checkHost(host);
        if (Objects.requireNonNull(command, "command").isEmpty()) {
            throw new IllegalArgumentException("no command given to start on host " + host);
        }
        Path parent = log.toAbsolutePath().getParent();
        if (parent != null) {
            Files.createDirectories(parent);
        }
        List<String> full = new ArrayList<>(List.of(ip.toString(), "netns", "exec", hosts.get(host).namespace()));
        full.addAll(command);
        Process process = new ProcessBuilder(full)
                .redirectErrorStream(true)
                .redirectOutput(log.toFile())
                .redirectInput(ProcessBuilder.Redirect.from(new File("/dev/null")))
                .start();
        processes.add(process);
        return process;
    }

    /** Cuts host {@code host} off: its bridge port goes down, so nothing passes either way. */
    public void cut(int host) throws IOException {
        checkOpen();
        checkHost(host);
        Exec.check(List.of(ip.toString(), "-n", bridgeNamespace, "link", "set", "h" + host, "down"));
    }

    /** Connects host {@code host} again, and returns once its link is up, so traffic passes at once. */
    public void heal(int host) throws IOException {
        checkOpen();
        checkHost(host);
        Exec.check(List.of(ip.toString(), "-n", bridgeNamespace, "link", "set", "h" + host, "up"));
        awaitLinkUp(hosts.get(host).namespace());
    }

    /**
     * Drops {@code percent} of the packets arriving at host {@code host}, at random, replacing any loss
     * set before; with nftables when it is installed, iptables otherwise.
     *
     * @throws IllegalStateException when neither tool is installed ({@link #lossUnavailableReason()})
     */
    public void loss(int host, int percent) throws IOException {
        LossTool tool = LossTool.preferred().orElseThrow(() -> new IllegalStateException(
                "cannot set a loss on host " + host + ": " + lossUnavailableReason().orElse("no loss tool")));
        loss(host, percent, tool);
    }

    /** {@link #loss(int, int)} with a given tool. */
    void loss(int host, int percent, LossTool tool) throws IOException {
        checkOpen();
        checkHost(host);
        if (percent < 0 || percent > 100) {
            throw new IllegalArgumentException("a loss of " + percent + "% on host " + host + " cannot be set; it must be 0 to 100");
        }
        LossTool before = lossTools.get(host);
        if (before != null && before != tool) {
            clearLoss(host);
        }
        tool.set(ip, hosts.get(host).namespace(), percent);
        lossTools.put(host, tool);
    }

    /** Stops dropping packets at host {@code host}; does nothing when no loss was set. */
    public void clearLoss(int host) throws IOException {
        checkOpen();
        checkHost(host);
        LossTool tool = lossTools.remove(host);
        if (tool != null) {
            tool.clear(ip, hosts.get(host).namespace());
        }
    }

    /**
     * Kills every process the lab started (and their descendants, and anything else still inside its
     * namespaces) with SIGKILL, waits for them to end, and deletes every namespace it made, which
     * removes the bridge and the veth pairs with them. Every step is tried even when an earlier one
     * failed. Closing again does nothing.
     *
     * @throws IllegalStateException listing what could not be removed
     */
    @Override
    public void close() {
        if (closed) {
            return;
        }
        closed = true;
        List<ProcessHandle> started = new ArrayList<>();
        for (Process process : processes) {
            process.descendants().forEach(started::add);
            started.add(process.toHandle());
        }
        List<String> problems = new ArrayList<>();
        Namespaces.remove(ip, namespaces, started, problems);
        try {
            Runtime.getRuntime().removeShutdownHook(shutdownHook);
        } catch (IllegalStateException shuttingDown) {
            // close() runs from the hook itself: nothing to remove
        }
        if (!problems.isEmpty()) {
            throw new IllegalStateException("network lab " + run + " was not fully removed: " + String.join("; ", problems));
        }
    }

    /**
     * Removes what crashed runs with {@code prefix} left: every namespace named
     * {@code PREFIX-PID-XXXX-...} whose process {@code PID} no longer exists, after killing the
     * processes still inside it. Labs of live processes, this one's included, are left alone.
     *
     * @return how many namespaces were removed
     */
    public static int cleanupStale(String prefix) throws IOException {
        checkPrefix(prefix);
        Optional<String> reason = unavailableReason();
        if (reason.isPresent()) {
            throw new IllegalStateException("no network namespace lab can run here, so none is left to clean: " + reason.get());
        }
        Path ip = Exec.find("ip").orElseThrow();
        Pattern ours = Pattern.compile(Pattern.quote(prefix) + "-(\\d{1,10})-[0-9a-f]{4}-(?:br|h\\d+)");
        List<String> stale = new ArrayList<>();
        for (String namespace : Namespaces.names(ip)) {
            Matcher m = ours.matcher(namespace);
            if (m.matches() && !isAlive(m.group(1))) {
                stale.add(namespace);
            }
        }
        List<String> problems = new ArrayList<>();
        Namespaces.remove(ip, stale, List.of(), problems);
        if (!problems.isEmpty()) {
            throw new IOException("stale network labs with prefix '" + prefix + "' were not fully removed: "
                    + String.join("; ", problems));
        }
        return stale.size();
    }

    @Override
    public String toString() {
        return "NetnsLab[" + run + ", " + hosts.size() + " hosts" + (closed ? ", closed]" : "]");
    }

    /** Makes the namespaces, the bridge, one veth per host, and each host's address. */
    private void build() throws IOException {
        addNamespace(bridgeNamespace);
        StringBuilder bridge = new StringBuilder("link add br0 type bridge\nlink set br0 up\n");
        for (Host host : hosts) {
            addNamespace(host.namespace());
            bridge.append("link add h").append(host.index()).append(" type veth peer name eth0 netns ")
                    .append(host.namespace()).append('\n')
                    .append("link set h").append(host.index()).append(" master br0 up\n");
        }
        Exec.check(List.of(ip.toString(), "-n", bridgeNamespace, "-batch", "-"), bridge.toString());
        for (Host host : hosts) {
            Exec.check(List.of(ip.toString(), "-n", host.namespace(), "-batch", "-"),
                    "link set lo up\n"
                            + "addr add " + host.address() + "/" + PREFIX_BITS + " broadcast " + BROADCAST + " dev eth0\n"
                            + "link set eth0 up\n");
        }
        for (Host host : hosts) {
            awaitLinkUp(host.namespace());
        }
    }

    private void addNamespace(String namespace) throws IOException {
        Exec.check(List.of(ip.toString(), "netns", "add", namespace));
        namespaces.add(namespace);
    }

    /** Waits until {@code eth0} of {@code namespace} is operationally up: the kernel then sends and delivers on it. */
    private void awaitLinkUp(String namespace) throws IOException {
        long deadline = System.nanoTime() + LINK_UP_WAIT.toNanos();
        String state;
        do {
            state = Exec.check(List.of(ip.toString(), "-n", namespace, "-o", "link", "show", "dev", "eth0"));
            if (state.contains(" state UP ")) {
                return;
            }
            pause(10);
        } while (System.nanoTime() < deadline);
        throw new IOException("eth0 of " + namespace + " is not up " + LINK_UP_WAIT.toSeconds() + " s after its link was set up: "
                + state.strip());
    }

    private void checkOpen() {
        if (closed) {
            throw new IllegalStateException("network lab " + run + " is closed");
        }
    }

    private void checkHost(int index) {
        if (index < 0 || index >= hosts.size()) {
            throw new IndexOutOfBoundsException("host " + index + " is not in lab " + run + "; its hosts are 0 to "
                    + (hosts.size() - 1));
        }
    }

    private void closeAtExit() {
        try {
            close();
        } catch (RuntimeException e) {
            System.err.println(e.getMessage());   // the JVM is exiting: stderr is all there is
        }
    }

    private static void checkPrefix(String prefix) {
        Objects.requireNonNull(prefix, "prefix");
        if (!PREFIX.matcher(prefix).matches()) {
            throw new IllegalArgumentException("lab prefix '" + prefix + "' is not allowed; it must be 1 to 16 lower case "
                    + "letters and digits, starting with a letter, e.g. smcnode");
        }
    }

    private static boolean isAlive(String pid) {
        return ProcessHandle.of(Long.parseLong(pid)).map(ProcessHandle::isAlive).orElse(false);
    }

    private static void pause(long millis) throws IOException {
        try {
            Thread.sleep(millis);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IOException("interrupted while waiting for a link", e);
        }
    }
}
