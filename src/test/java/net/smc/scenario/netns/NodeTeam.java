package net.smc.scenario.netns;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.security.SecureRandom;
import java.time.Duration;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.TimeUnit;
import java.util.function.Predicate;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import net.smc.core.security.Claims;
import net.smc.core.security.Credential;
import net.smc.core.security.KeyFiles;
import net.smc.core.security.SigningKey;

/**
 * A team of {@code smc node} processes on the hosts of a {@link NetnsLab}, for multi-process scenario
 * tests: it issues every vehicle a key and a credential of one mission authority, starts each vehicle's
 * node in a host's namespace ({@code java -cp <this JVM's class path> net.smc.demo.Main node ...}, so
 * nothing needs {@code installDist}), watches the nodes' logs for their decisions, and reads their
 * status views through a {@link ViewProbe} on a host of its own (this JVM cannot reach the lab's
 * subnet). Every node binds {@code HOST:}{@value #NODE_PORT} and shares the broadcast port
 * {@value #BROADCAST_PORT} of the lab's subnet. The lab owns the processes: closing it kills them all.
 */
final class NodeTeam {
    static final int NODE_PORT = 4000;
    static final int BROADCAST_PORT = 47474;
    /** The mission of {@code missions/reconnaissance.instance.xml}: comTimeout 500 ms, failureTimeout 3000 ms, one backup. */
    static final String MISSION = "HouseSurvey";
    private static final long PROBE_INTERVAL_MILLIS = 200;
    private static final int TAIL_LINES = 40;
    private static final Duration UP_WAIT = Duration.ofSeconds(30);
    /** An event line of {@code smc node}: {@code CellEvent.toString()}, epoch ms first. */
    private static final Pattern EVENT = Pattern.compile("\\s*(\\d+) (\\S+)\\s+([A-Z_]+)\\s+(.*)");

    /** A vehicle of the reconnaissance mission: its id, its capability, and whether it starts as commander. */
    record Vehicle(String id, List<String> resources, List<String> tasks, boolean commander) {
        /** Able to command (and so to back up the commander) and to aggregate. */
        static Vehicle commander(String id) {
            return new Vehicle(id, List.of("communication"), List.of("Aggregator"), true);
        }

        /** A surveyor able to carry the hazard-detector and relay roles too. */
        static Vehicle surveyor(String id) {
            return new Vehicle(id, List.of("motion", "video", "chemical", "communication"),
                    List.of("Explorer", "HazardDetector", "Relay"), false);
        }

        static Vehicle aggregator(String id) {
            return new Vehicle(id, List.of("communication"), List.of("Aggregator"), false);
        }

        static Vehicle detector(String id) {
            return new Vehicle(id, List.of("motion", "chemical"), List.of("HazardDetector"), false);
        }

        static Vehicle relay(String id) {
            return new Vehicle(id, List.of("motion", "communication"), List.of("Relay"), false);
        }
    }

    /** A started node: its vehicle, host, address, log and process. */
    record Node(Vehicle vehicle, int host, String address, Path log, Process process) {
        String id() {
            return vehicle.id();
        }
    }

    /** One decision a node logged: when (the node's clock, epoch ms), which vehicle, what kind, the detail. */
    record Event(long timeMillis, String vehicle, String kind, String detail) {
        static Optional<Event> parse(String line) {
            Matcher m = EVENT.matcher(line);
            return m.matches() ? Optional.of(new Event(Long.parseLong(m.group(1)), m.group(2), m.group(3), m.group(4)))
                    : Optional.empty();
        }
    }

    private final NetnsLab lab;
    private final Path dir;
    private final Path keys;
    private final Path mission;
    private final Path repository;
    private final Map<String, Node> nodes = new LinkedHashMap<>();
    private Path views;
    private Path probeLog;

    /**
     * A team on {@code lab}, its keys, logs and views under {@code dir}, issuing credentials to {@code vehicles}.
     *
     * @param project the project's folder: the mission is {@code missions/reconnaissance.instance.xml} in it,
     *                the policy repository {@code policies/}
     */
    NodeTeam(NetnsLab lab, Path dir, Path project, List<String> vehicles) throws IOException {
        this.lab = lab;
        this.dir = dir;
        this.keys = Files.createDirectories(dir.resolve("keys"));
        this.mission = project.resolve("missions/reconnaissance.instance.xml");
        this.repository = project.resolve("policies");
        issue(vehicles);
    }

    /** The mission authority's key pair, and each vehicle's key pair and credential for {@value #MISSION}, valid 1 h. */
    private void issue(List<String> vehicles) throws IOException {
        SecureRandom random = new SecureRandom();
        SigningKey authority = SigningKey.generate(random);
        Files.writeString(keys.resolve("authority.pub"), KeyFiles.publicKeyText(authority.verificationKey(), "authority"));
        long now = System.currentTimeMillis();
        for (String id : vehicles) {
            SigningKey key = SigningKey.generate(random);
            Credential credential = Credential.issue(new Claims(id, key.verificationKey(), MISSION, now - 60_000,
                    now + 3_600_000), authority);
            Files.writeString(keys.resolve(id + ".key"), KeyFiles.privateKeyText(key, KeyFiles.Use.VEHICLE, id));
            Files.setPosixFilePermissions(keys.resolve(id + ".key"),
                    java.nio.file.attribute.PosixFilePermissions.fromString("rw-------"));
            Files.writeString(keys.resolve(id + ".cred"), KeyFiles.credentialText(credential, id));
        }
    }

    /** Starts {@code vehicle}'s node on host {@code host} (its log: DIR/ID.log, emptied); returns at once. */
    Node start(int host, Vehicle vehicle) throws IOException {
        String address = lab.host(host).address() + ":" + NODE_PORT;
        List<String> command = new ArrayList<>(List.of(
                Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                // A quick start and a small footprint: ten JVMs share two cores here.
                "-XX:TieredStopAtLevel=1", "-XX:+UseSerialGC", "-Xmx128m", "-Xshare:auto",
                "-cp", System.getProperty("java.class.path"), "net.smc.demo.Main", "node",
                "--mission", mission.toString(), "--repository", repository.toString(),
                "--credential", keys.resolve(vehicle.id() + ".cred").toString(),
                "--key", keys.resolve(vehicle.id() + ".key").toString(),
                "--authority", keys.resolve("authority.pub").toString(),
                "--bind", address, "--broadcast", lab.broadcastAddress() + ":" + BROADCAST_PORT, "--id", vehicle.id()));
        if (vehicle.commander()) {
            command.add("--commander");
        }
        if (!vehicle.resources().isEmpty()) {
            command.addAll(List.of("--resources", String.join(",", vehicle.resources())));
        }
        if (!vehicle.tasks().isEmpty()) {
            command.addAll(List.of("--tasks", String.join(",", vehicle.tasks())));
        }
        Path log = dir.resolve(vehicle.id() + ".log");
        Node node = new Node(vehicle, host, address, log, lab.start(host, command, log));
        nodes.put(vehicle.id(), node);
        return node;
    }

    /** Waits until every one of {@code started} has written its up line. */
    void awaitUp(List<Node> started) throws IOException, InterruptedException {
        for (Node node : started) {
            LogWatch.await(node.log(), "the up line of " + node.id(), line -> line.startsWith("up: vehicle " + node.id() + " "),
                    UP_WAIT);
        }
    }

    /**
     * Starts the {@link ViewProbe} on host {@code host}, asking the nodes of {@code nodeHosts} (started or
     * not) every {@value #PROBE_INTERVAL_MILLIS} ms; returns once it runs.
     */
    void startProbe(int host, List<Integer> nodeHosts) throws IOException, InterruptedException {
        views = dir.resolve("views.txt");
        probeLog = dir.resolve("probe.log");
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-XX:TieredStopAtLevel=1", "-XX:+UseSerialGC", "-Xmx64m",
                "-cp", System.getProperty("java.class.path"), ViewProbe.class.getName(), views.toString(),
                String.valueOf(PROBE_INTERVAL_MILLIS)));
        nodeHosts.forEach(h -> command.add(lab.host(h).address() + ":" + NODE_PORT));
        lab.start(host, command, probeLog);
        LogWatch.await(probeLog, "the view probe", line -> line.startsWith("probing "), UP_WAIT);
    }

    Node node(String id) {
        Node node = nodes.get(id);
        if (node == null) {
            throw new IllegalArgumentException("no node '" + id + "' was started; started: " + nodes.keySet());
        }
        return node;
    }

    /** The nodes started so far whose process still runs. */
    List<Node> alive() {
        return nodes.values().stream().filter(n -> n.process().isAlive()).toList();
    }

    /** Kills a node's process with SIGKILL and waits for it to end. */
    void kill(Node node) throws InterruptedException {
        node.process().destroyForcibly();
        if (!node.process().waitFor(10, TimeUnit.SECONDS)) {
            throw new AssertionError("node " + node.id() + " did not end within 10 s of SIGKILL");
        }
    }

    /**
     * The views of the probe's latest round, by vehicle id; nodes that did not answer are absent, and so
     * are nodes still starting (whose status responder answers {@code {}} until the cell is built).
     */
    Map<String, NodeView> views() throws IOException {
        Map<String, NodeView> byVehicle = new LinkedHashMap<>();
        for (String line : viewLines()) {
            int space = line.indexOf(' ');
            if (line.startsWith("round ") || space < 0 || List.of("-", "{}").contains(line.substring(space + 1))) {
                continue;
            }
            NodeView view = NodeView.parse(line.substring(space + 1));
            byVehicle.put(view.vehicle(), view);
        }
        return byVehicle;
    }

    /** Polls the views until {@code wanted} accepts them; answers them. */
    Map<String, NodeView> awaitViews(String what, Predicate<Map<String, NodeView>> wanted, Duration timeout)
            throws IOException, InterruptedException {
        long deadline = System.nanoTime() + timeout.toNanos();
        while (true) {
            Map<String, NodeView> current = views();
            if (wanted.test(current)) {
                return current;
            }
            if (System.nanoTime() > deadline) {
                throw new AssertionError("waited " + timeout.toMillis() + " ms for " + what + "; the last views:\n"
                        + String.join("\n", viewLines()));
            }
            Thread.sleep(PROBE_INTERVAL_MILLIS / 2);
        }
    }

    /** The first event of {@code kind} whose detail matches {@code detail} in {@code node}'s log, once there is one. */
    Event awaitEvent(Node node, String kind, String detail, Duration timeout) throws IOException, InterruptedException {
        Pattern pattern = Pattern.compile(detail);
        String line = LogWatch.await(node.log(), kind + " '" + detail + "' of " + node.id(),
                l -> Event.parse(l).filter(e -> e.kind().equals(kind) && pattern.matcher(e.detail()).matches()).isPresent(),
                timeout);
        return Event.parse(line).orElseThrow();
    }

    /** The first event of {@code kind} in the log of any of {@code among}, once there is one. */
    Event awaitAnyEvent(List<Node> among, String kind, Duration timeout) throws IOException, InterruptedException {
        long deadline = System.nanoTime() + timeout.toNanos();
        while (true) {
            for (Node node : among) {
                for (String line : LogWatch.lines(node.log())) {
                    Optional<Event> event = Event.parse(line).filter(e -> e.kind().equals(kind));
                    if (event.isPresent()) {
                        return event.get();
                    }
                }
            }
            if (System.nanoTime() > deadline) {
                throw new AssertionError("waited " + timeout.toMillis() + " ms for " + kind + " in the logs of "
                        + among.stream().map(Node::id).toList());
            }
            Thread.sleep(LogWatch.POLL_MILLIS);
        }
    }

    /** Every event of {@code node} so far. */
    List<Event> events(Node node) throws IOException {
        return LogWatch.lines(node.log()).stream().map(Event::parse).flatMap(Optional::stream).toList();
    }

    /**
     * For a failure message: each node's state and the last lines of its log (leaving out what policies
     * print, which repeats at every discovery), then the probe's latest views.
     */
    String report() {
        StringBuilder b = new StringBuilder();
        for (Node node : nodes.values()) {
            b.append("---- ").append(node.id()).append(" on host ").append(node.host()).append(" (").append(node.address())
                    .append(", ").append(node.process().isAlive() ? "running" : "ended " + node.process().exitValue())
                    .append("), last lines of ").append(node.log()).append(" without 'policy:' lines:\n");
            tail(node.log()).forEach(line -> b.append("  ").append(line).append('\n'));
        }
        b.append("---- probe views:\n");
        try {
            viewLines().forEach(line -> b.append("  ").append(line).append('\n'));
        } catch (IOException e) {
            b.append("  (unreadable: ").append(e.getMessage()).append(")\n");
        }
        return b.toString();
    }

    private static List<String> tail(Path log) {
        try {
            List<String> lines = LogWatch.lines(log).stream().filter(line -> !line.startsWith("policy: ")).toList();
            return lines.subList(Math.max(0, lines.size() - TAIL_LINES), lines.size());
        } catch (IOException e) {
            return List.of("(unreadable: " + e.getMessage() + ")");
        }
    }

    private List<String> viewLines() throws IOException {
        if (views == null) {
            return List.of();
        }
        try {
            return Files.readAllLines(views);
        } catch (NoSuchFileException e) {
            return List.of();
        }
    }
}
