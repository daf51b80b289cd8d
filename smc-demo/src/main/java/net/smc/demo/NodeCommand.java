package net.smc.demo;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.TreeSet;
import java.util.concurrent.Callable;
import java.util.function.Supplier;
import java.util.regex.Pattern;
import net.smc.core.capability.CapabilityDescription;
import net.smc.core.capability.TaskDescription;
import net.smc.sim.task.TaskCatalog;
import net.smc.core.host.CellHost;
import net.smc.core.transport.Address;
import net.smc.core.transport.udp.UdpSettings;
import net.smc.policy.api.PolicyRepository;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;

/**
 * {@code smc node}: runs one vehicle's self-managed cell on the network ({@link CellHost}: Netty UDP,
 * authenticated traffic, status queries) until the process is told to end. The vehicle is the one
 * its credential names; the mission authority's public key decides whom it trusts. What it decides
 * goes to standard output ({@link NodeLog}).
 *
 * <p>Arguments are checked before anything is read (usage errors, exit status 2); then the key,
 * credential, authority and mission files are read and checked against each other ({@link NodeFiles};
 * exit status 1, naming the option, the file and what is wrong with it); then the sockets are bound.
 * The process's shutdown ends the node through a {@link StopSignal}.
 */
@Command(name = "node", mixinStandardHelpOptions = true, versionProvider = Main.Version.class,
        description = {
            "Runs one vehicle's self-managed cell over UDP until the process is ended (SIGTERM or SIGINT "
                    + "close it cleanly): it discovers the team, takes or assigns roles, sends heartbeats, "
                    + "detects failures and merges with teams it meets, as the mission's policies decide. "
                    + "All its traffic is authenticated: its own credential and every peer's must be signed "
                    + "by the mission authority of --authority, for the mission of --mission.",
            "Standard output, one line each: first 'up: vehicle ID of mission M at ADDR:PORT ...', then every "
                    + "decision of the cell (epoch ms, vehicle, kind, detail), what policies print (prefixed "
                    + "'" + NodeLog.POLICY_PREFIX + "'), and 'down: ...' when it stops.",
            "'smc status --node ADDR:PORT' (the --bind address) asks it for its view."},
        exitCodeListHeading = "%nExit status:%n",
        exitCodeList = {
            "0:stopped on request (in-process); a process ended by SIGTERM or SIGINT closes cleanly, then exits "
                    + "with the JVM's status for the signal (143, 130)",
            "1:a file cannot be read or is refused (the mission's errors are listed; a key, credential or authority "
                    + "file is named with its problem), the credential does not verify, or --bind cannot be bound",
            "2:usage error: a missing or malformed option, a bad name in --resources or --tasks, --id not matching "
                    + "the credential, no policy repository"})
final class NodeCommand implements Callable<Integer> {
    /** Resource and task names: what a capability description can carry, and free of separators. */
    static final Pattern NAME = Pattern.compile("[A-Za-z][A-Za-z0-9_.-]{0,63}");
    /** The tasks a node may advertise with --tasks. */
    static final TaskCatalog TASKS = TaskCatalog.standard();

    private final Io io;
    private final Supplier<StopSignal> stops;

    @Spec
    CommandSpec spec;

    @Option(names = "--mission", required = true, paramLabel = "INSTANCE.xml",
            description = "The mission instance file (its class file beside it, as 'smc validate' reads them).")
    Path mission;

    @Option(names = "--credential", required = true, paramLabel = "FILE",
            description = "This vehicle's credential (ID.cred, from 'smc keys issue'); the vehicle id comes from it.")
    Path credential;

    @Option(names = "--key", required = true, paramLabel = "FILE",
            description = "This vehicle's private key (ID.key): the one its credential vouches for.")
    Path key;

    @Option(names = "--authority", required = true, paramLabel = "FILE",
            description = "The mission authority's public key (authority.pub): every credential must be signed by it.")
    Path authority;

    @Option(names = "--bind", required = true, paramLabel = "ADDR:PORT", converter = AddressConverter.class,
            description = "This node's unicast address: an IPv4 address of this host (not 0.0.0.0: other nodes are told "
                    + "to reply to it) and a UDP port of its own. Status queries are answered from it.")
    Address bind;

    @Option(names = "--broadcast", required = true, paramLabel = "ADDR:PORT", converter = AddressConverter.class,
            description = "The team's broadcast address and port: the subnet's broadcast address (127.255.255.255 on "
                    + "one machine) and the port every node of the team shares, e.g. 10.0.0.255:"
                    + UdpSettings.DEFAULT_BROADCAST_PORT + ".")
    Address broadcast;

    @Option(names = "--commander", description = "Start as the acting commander (it serves the team the mission's policies).")
    boolean commander;

    @Option(names = "--resources", split = ",", paramLabel = "R[,R...]", hideParamSyntax = true,
            description = "The vehicle's resources, e.g. motion,video,communication (default: none).")
    List<String> resources = List.of();

    @Option(names = "--tasks", split = ",", paramLabel = "T[,T...]", hideParamSyntax = true,
            description = "The vehicle's tasks, from Aggregator, Assist, Beacon, Explorer, HazardDetector, Navigator, Relay (default: none); each is advertised with its full capability description.")
    List<String> tasks = List.of();

    @Option(names = "--allow-path", paramLabel = "DIR",
            description = "Also allow the mission instance's <missionClass href> to name a file in DIR or below "
                    + "(repeatable; by default only the instance's own folder and below).")
    List<Path> allowPaths = new java.util.ArrayList<>();

    @Option(names = "--repository", paramLabel = "DIR",
            description = "The policy repository (default: the " + CellOptions.DEFAULT_REPOSITORY + "/ folder beside the "
                    + "mission file's folder, as missions/ and policies/ sit in the project; else the "
                    + CellOptions.DEFAULT_REPOSITORY + "/ folder of the current directory).")
    Path repository;

    @Option(names = "--id", paramLabel = "ID",
            description = "The vehicle id the credential must name: a check against starting the wrong credential.")
    String id;

    NodeCommand(Io io, Supplier<StopSignal> stops) {
        this.io = io;
        this.stops = stops;
    }

    @Override
    public Integer call() {
        UdpSettings udp = udpSettings();
        names("--resources", resources);
        names("--tasks", tasks);
        for (String task : tasks) {
            if (!TASKS.contains(task)) {
                throw usage("--tasks '" + task + "' is not a known task; the known tasks are "
                        + String.join(", ", TASKS.names()));
            }
        }
        PolicyRepository repo = repository();
        NodeFiles.Node node;
        try {
            node = new NodeFiles(io.workingDir(), CellOptions.allowedFolders(spec, io.workingDir(), allowPaths)).read(key, credential, authority, mission, repo, System.currentTimeMillis());
        } catch (NodeFiles.Refused e) {
            e.details().forEach(io.stderr()::println);
            io.stderr().println("smc node: " + e.getMessage());
            io.stderr().flush();
            return 1;
        }
        if (id != null && !id.equals(node.identity().id())) {
            throw usage("--id '" + id + "' does not match --credential " + credential + ", which is for vehicle '"
                    + node.identity().id() + "'");
        }
        return run(node, udp, repo);
    }

    /** Runs the cell until the stop signal fires; 1 when it cannot start (the sockets, the cell's boot). */
    private int run(NodeFiles.Node node, UdpSettings udp, PolicyRepository repo) {
        String vehicle = node.identity().id();
        CapabilityDescription description = describe(vehicle, resources, tasks);
        NodeLog log = new NodeLog(io.stdout());
        CellHost.Settings settings = CellHost.settings(vehicle, node.mission(), description, repo)
                .udp(udp).commander(commander).security(node.identity(), node.trust())
                .trace(log::event).output(log::policy);
        try (StopSignal stop = stops.get()) {
            CellHost host;
            try {
                host = CellHost.open(settings);
            } catch (IOException | RuntimeException e) {
                io.stderr().println("smc node: vehicle '" + vehicle + "' cannot start: " + e.getMessage());
                io.stderr().flush();
                return 1;
            }
            String why;
            try (host) {
                log.up("up: vehicle " + vehicle + " of mission " + node.mission().instanceName() + " at "
                        + host.status().localAddress() + ", broadcast " + broadcast + ", commander: "
                        + (commander ? "yes" : "no") + ", resources " + description.resources() + ", tasks "
                        + description.taskNames());
                try {
                    why = stop.await();
                } catch (InterruptedException e) {
                    why = "interrupted";
                    Thread.currentThread().interrupt();
                }
            }
            log.line("down: vehicle " + vehicle + " stopped: " + why);
        }
        return 0;
    }

    /**
     * The vehicle's capability description: its resources, and the Table V description of each of
     * its tasks as the task catalogue gives it (what discovery summaries and full capability
     * replies carry).
     *
     * @throws IllegalArgumentException naming the known tasks, for a task the catalogue does not know
     */
    static CapabilityDescription describe(String vehicle, List<String> resources, List<String> tasks) {
        List<TaskDescription> described = new ArrayList<>();
        for (String task : new TreeSet<>(tasks)) {
            described.add(TASKS.describe(task));
        }
        return CapabilityDescription.of(vehicle, new TreeSet<>(resources), described);
    }

    private UdpSettings udpSettings() {
        if (bind.host().equals("0.0.0.0")) {
            throw usage("--bind " + bind + ": 0.0.0.0 cannot be told to other nodes as where to reply; give an "
                    + "address of this host, e.g. 10.0.0.7:" + bind.port());
        }
        if (bind.port() == broadcast.port()) {
            throw usage("--bind " + bind + " has the port of --broadcast " + broadcast + "; a node needs a unicast "
                    + "port of its own beside the team's shared broadcast port");
        }
        return new UdpSettings(bind.host(), bind.port(), null, broadcast.host(), broadcast.port(),
                UdpSettings.defaults().receiveBufferBytes());
    }

    private void names(String option, List<String> given) {
        for (String name : given) {
            if (!NAME.matcher(name).matches()) {
                throw usage(option + " '" + name + "' is not a name: it must be 1 to 64 of A-Z a-z 0-9 _ . -, starting "
                        + "with a letter (several are separated by commas)");
            }
        }
    }

    /** --repository; else policies/ beside the mission's folder; else policies/ of the current directory. */
    private PolicyRepository repository() {
        if (repository != null) {
            Path dir = io.workingDir().resolve(repository);
            if (!Files.isDirectory(dir)) {
                throw usage("--repository '" + repository + "': " + (Files.exists(dir) ? "not a directory" : "no such directory"));
            }
            return new PolicyRepository(dir);
        }
        Path missionDir = io.workingDir().resolve(mission).toAbsolutePath().normalize().getParent();
        Path beside = missionDir == null || missionDir.getParent() == null ? null
                : missionDir.getParent().resolve(CellOptions.DEFAULT_REPOSITORY);
        Path here = io.workingDir().resolve(CellOptions.DEFAULT_REPOSITORY);
        for (Path dir : beside == null ? List.of(here) : List.of(beside, here)) {
            if (Files.isDirectory(dir)) {
                return new PolicyRepository(dir);
            }
        }
        throw usage("no --repository given, and no " + CellOptions.DEFAULT_REPOSITORY + "/ folder "
                + (beside == null ? "" : "beside the mission's folder (" + beside + ") or ") + "in the current directory ("
                + here.toAbsolutePath() + "); a node needs the policy repository");
    }

    private ParameterException usage(String message) {
        return new ParameterException(spec.commandLine(), message);
    }
}
