package net.smc.demo;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.io.Writer;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.Callable;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.FutureTask;
import java.util.concurrent.RunnableFuture;
import java.util.concurrent.ThreadFactory;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.stream.Stream;

import net.smc.core.cell.Scheme;
import net.smc.core.mission.Mission;
import net.smc.core.mission.MissionException;
import net.smc.core.mission.MissionLoader;
import net.smc.policy.api.PolicyRepository;
import net.smc.sim.experiment.Calibration;
import net.smc.sim.experiment.CpuCosts;
import net.smc.sim.experiment.GeneratedMission;
import net.smc.sim.experiment.MissionGenerator;
import net.smc.sim.experiment.RadioNetwork;
import net.smc.sim.experiment.SetupResult;
import net.smc.sim.experiment.SetupTimeCsv;
import net.smc.sim.experiment.SetupTimeRun;
import net.smc.sim.experiment.TreeShape;
import net.smc.sim.experiment.UdpSetupTimeRun;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;

/**
 * {@code smc experiment setup-time}: the paper's Fig. 8. For each number of roles a mission is
 * generated ({@link MissionGenerator}), and each scheme's team is set up {@code --runs} times on the
 * simulated radio network ({@link SetupTimeRun}), and with {@code --transport udp} on loopback UDP
 * ({@link UdpSetupTimeRun}), seeds {@code --seed + run}. Writes
 * {@code setup-time.csv}, {@code setup-time.png}, the shape of the medians ({@code shape.txt}:
 * {@link SetupTimeShape}) and the CPU costs used ({@code costs.properties}) in {@code --out}; shows a
 * progress bar on standard error, and each point's summary and then the shape on standard output.
 */
@Command(name = "setup-time", mixinStandardHelpOptions = true, versionProvider = Main.Version.class,
        description = {"Measures the mission set-up time against the number of roles (the paper's Fig. 8), for the "
                + "distributed and the centralised scheme, on a simulated ad-hoc radio network with each cell's CPU "
                + "charged from costs measured on this machine (or read with --costs); with --transport udp (or sim,udp) "
                + "the same teams on real Netty UDP over loopback, timed on the wall clock.",
            "Writes DIR/setup-time.csv (one row per run), DIR/setup-time.png (median and p10-p90 band per scheme "
                    + "and transport), DIR/shape.txt (the medians, each scheme's growth from its fewest roles, "
                    + "centralised over distributed, and where the faster scheme changes; also printed at the end) "
                    + "and DIR/costs.properties."},
        exitCodeListHeading = "%nExit status:%n",
        exitCodeList = {"0:every run finished (a run whose roles did not all start is a row with an empty setup_ms)",
            "2:usage error"})
final class SetupTimeCommand implements Callable<Integer> {
    private final Io io;

    @Spec
    CommandSpec spec;

    @Option(names = "--roles", split = ",", paramLabel = "N", defaultValue = "5,10,20,50,100,200,500,1000",
            description = "Numbers of roles, the commander's included (default: ${DEFAULT-VALUE}).")
    List<Integer> roles;

    @Option(names = "--schemes", split = ",", paramLabel = "SCHEME", defaultValue = "distributed,centralised",
            description = "distributed, centralised, or both (default: ${DEFAULT-VALUE}).")
    List<String> schemes;

    /** The most runs a point may have: a million runs of the smallest point take days. */
    static final int MAX_RUNS = 100_000;

    @Option(names = "--runs", defaultValue = "20", description = "Runs per point, 1 to 100,000 (default: ${DEFAULT-VALUE}).")
    int runs;

    @Option(names = "--seed", defaultValue = "1", description = "Seed of the first run (default: ${DEFAULT-VALUE}).")
    long seed;

    @Option(names = "--out", required = true, paramLabel = "DIR", description = "Where the results go (created).")
    Path out;

    @Option(names = "--transport", split = ",", defaultValue = "sim", paramLabel = "sim|udp",
            description = {"sim: the simulated radio network (default); udp: the same teams on real Netty UDP over "
                    + "loopback, each cell with its own threads and sockets and signed traffic, at most "
                    + UdpSetupTimeRun.MAX_ROLES + " roles; sim,udp: both, on one chart and in one CSV."})
    List<String> transports;

    @Option(names = "--depth", defaultValue = "4", description = "Levels of the management tree (default: ${DEFAULT-VALUE}).")
    int depth;

    @Option(names = "--fan-out", paramLabel = "F",
            description = "Children per manager (default: the smallest that holds the roles in --depth levels).")
    Integer fanOut;

    @Option(names = "--costs", paramLabel = "FILE",
            description = "CPU costs to use (a costs.properties of an earlier run) instead of measuring them.")
    Path costsFile;

    @Option(names = "--limit", defaultValue = "300000", paramLabel = "MS",
            description = "Time after which a run that has not set up is given up: simulated ms, wall ms over udp "
                    + "(default: ${DEFAULT-VALUE}).")
    long limitMillis;

    @Option(names = "--policies", defaultValue = "policies", paramLabel = "DIR",
            description = "The project's policy repository, for boot/events.p2 (default: ${DEFAULT-VALUE}).")
    Path policies;

    @Option(names = "--jobs", paramLabel = "J",
            description = {"Simulated runs of a point run on J threads at once (default: one per processor). Each "
                    + "run is a seeded simulation with its own clock and charged CPU, so the results do not depend on J; "
                    + "runs over UDP, timed on the wall clock, always run one at a time."})
    Integer jobs;

    @Mixin
    NetworkOptions network;

    @Option(names = "--spare", paramLabel = "PCT", defaultValue = "0", description = {"Vehicles beyond the seats, in "
            + "percent of each role's seats, rounded up, built for that role like the others (default: ${DEFAULT-VALUE}: "
            + "one vehicle per seat). Simulated runs only."})
    int sparePercent;

    @Option(names = "--warmup", paramLabel = "N", defaultValue = "0", description = {"Over UDP, N runs of each point "
            + "before its recorded runs, not recorded (seeds after theirs): the JVM compiles the cells' code as it runs "
            + "it, and a point's first runs over UDP are mostly that compiling (default: ${DEFAULT-VALUE}: every run "
            + "recorded, as a vehicle's first set-up after it starts). Simulated runs charge measured, compiled costs "
            + "and take no warm-up."})
    int warmup;

    @Option(names = "--verbose", description = {"After each simulated run, a report on standard output: when the roles "
            + "of each level of the tree started, where the slowest of the deepest level's roles waited, the "
            + "busiest cell's charged CPU by category and the datagrams it received by kind, and the team's "
            + "datagrams and bytes by kind."})
    boolean verbose;

    SetupTimeCommand(Io io) {
        this.io = io;
    }

    @Override
    public Integer call() throws Exception {
        List<Scheme> schemeList = schemes();
        checkArguments();
        quietUndeliveredWarnings();
        RadioNetwork radio = network.radio(spec);
        boolean sim = transports.contains("sim");
        Path boot = io.workingDir().resolve(policies).resolve("boot/events.p2");
        if (!Files.isRegularFile(boot)) {
            throw new ParameterException(spec.commandLine(), "--policies " + policies + ": no boot/events.p2 in it; "
                    + "it must be the project's policies/ folder");
        }
        Path dir = OutFolder.make(spec, io.workingDir(), out);
        Map<Integer, TreeShape> shapes = new LinkedHashMap<>();
        for (int n : roles) {
            try {
                shapes.put(n, fanOut == null ? TreeShape.of(n, depth) : new TreeShape(n, depth, fanOut));
            } catch (IllegalArgumentException e) {
                throw new ParameterException(spec.commandLine(), "--roles " + n + ": " + e.getMessage());
            }
        }
        Path work = Files.createTempDirectory("smc-setup-time");
        try {
            return run(schemeList, radio, sim, dir, boot, shapes, work);
        } finally {
            deleteTree(work);
        }
    }

    /** A point's generated mission, loaded for each scheme. */
    private record Prepared(GeneratedMission generated, Map<Scheme, Mission> missions) {
    }

    /**
     * Generates and loads every point's mission before any run, so that a shape whose mission cannot
     * load (a manager of hundreds of role types whose role-mission outgrows a policy reply, say) is a
     * usage error naming it, not a failure after the points before it have run.
     */
    private Map<TreeShape, Prepared> prepare(Map<Integer, TreeShape> shapes, List<Scheme> schemeList, Path work, Path boot)
            throws IOException {
        Map<TreeShape, Prepared> prepared = new LinkedHashMap<>();
        for (TreeShape shape : shapes.values()) {
            GeneratedMission g = MissionGenerator.write(shape, work.resolve("m" + shape.roles()), boot);
            MissionLoader loader = new MissionLoader(new PolicyRepository(g.repository()));
            Map<Scheme, Mission> missions = new LinkedHashMap<>();
            for (Scheme scheme : schemeList) {
                try {
                    missions.put(scheme, loader.load(g.instanceFile(scheme)));
                } catch (MissionException e) {
                    throw new ParameterException(spec.commandLine(), "--roles " + shape.roles() + " (depth "
                            + shape.depth() + ", fan-out " + shape.fanOut() + "): the generated " + scheme.name()
                            .toLowerCase(Locale.ROOT) + " mission does not load: " + e.errors().get(0).message()
                            + (e.errors().size() > 1 ? " (and " + (e.errors().size() - 1) + " more)" : "")
                            + "; a deeper tree or a smaller --fan-out gives each manager fewer roles");
                }
            }
            prepared.put(shape, new Prepared(g, missions));
        }
        return prepared;
    }

    private Integer run(List<Scheme> schemeList, RadioNetwork radio, boolean sim, Path dir, Path boot,
                        Map<Integer, TreeShape> shapes, Path work) throws Exception {
        CpuCosts costs = null;
        if (sim && costsFile != null) {
            try {
                costs = CpuCosts.load(io.workingDir().resolve(costsFile), note -> io.stdout().println("costs: " + note));
            } catch (NoSuchFileException e) {
                throw new ParameterException(spec.commandLine(), "--costs " + costsFile + ": no such file");
            } catch (IOException | IllegalArgumentException e) {
                throw new ParameterException(spec.commandLine(), "--costs " + costsFile + ": " + e.getMessage());
            }
        }
        Map<TreeShape, Prepared> prepared = prepare(shapes, schemeList, work, boot);
        if (!sim) {
            io.stdout().println("transport: Netty UDP on loopback, signed traffic, wall-clock times");
        } else if (costs == null) {
            io.stderr().println("calibrating: measuring the CPU cost of each operation ...");
            io.stderr().flush();
            costs = Calibration.measure(boot, MissionGenerator.write(TreeShape.of(20, 4), work.resolve("calibration"), boot));
        }
        if (warmup > 0) {
            io.stdout().println("warm-up: " + warmup + " unrecorded run" + (warmup == 1 ? "" : "s")
                    + " of each point over UDP before its recorded runs");
        }
        CpuCosts charged = costs;
        if (sim) {
            costs.save(dir.resolve("costs.properties"));
            io.stdout().println("network: " + radio);
            io.stdout().println("team: one vehicle per seat" + (sparePercent == 0 ? ""
                    : " and " + sparePercent + "% more of each role, rounded up"));
            io.stdout().println("CPU costs: " + costs);
        }
        io.stdout().flush();

        List<SetupResult> results = new ArrayList<>();
        int total = shapes.size() * schemeList.size() * transports.size() * runs;
        long t0 = System.nanoTime();
        int threads = jobs == null ? Runtime.getRuntime().availableProcessors() : jobs;
        ExecutorService pool = Executors.newFixedThreadPool(Math.min(threads, runs), runner());
        try (Writer csv = Files.newBufferedWriter(dir.resolve("setup-time.csv"))) {
            SetupTimeCsv.writeHeader(csv);
            for (TreeShape shape : shapes.values()) {
                GeneratedMission g = prepared.get(shape).generated();
                for (Scheme scheme : schemeList) {
                    Mission mission = prepared.get(shape).missions().get(scheme);
                    for (String transport : transports) {
                        long pointStart = System.nanoTime();
                        progress(results.size(), total, shape.roles(), scheme, t0);
                        // Over UDP a run is timed on the wall clock, so it runs alone, on this thread.
                        boolean alone = transport.equals("udp");
                        for (int w = 1; alone && w <= warmup; w++) {
                            progress(results.size(), total, shape.roles() + " roles, warm-up " + w + "/" + warmup, t0);
                            UdpSetupTimeRun.run(g, mission, scheme, runs + w, seed + runs + w, limitMillis);
                        }
                        List<RunnableFuture<SimulatedRun>> point = new ArrayList<>();
                        for (int run = 1; run <= runs; run++) {
                            int r0 = run;
                            Callable<SimulatedRun> task = alone
                                    ? () -> new SimulatedRun(UdpSetupTimeRun.run(g, mission, scheme, r0, seed + r0,
                                            limitMillis), "")
                                    : () -> simulate(g, mission, scheme, r0, radio, charged);
                            RunnableFuture<SimulatedRun> f = new FutureTask<>(task);
                            if (!alone) {
                                pool.execute(f);
                            }
                            point.add(f);
                        }
                        for (RunnableFuture<SimulatedRun> f : point) {
                            if (alone) {
                                f.run();
                            }
                            SimulatedRun r = outcome(f);
                            verbose(shape.roles(), scheme, r.result().run(), r.report());
                            results.add(r.result());
                            SetupTimeCsv.writeRow(csv, r.result());
                            csv.flush();
                            progress(results.size(), total, shape.roles(), scheme, t0);
                        }
                        summary(results, shape.roles(), scheme, transport, (System.nanoTime() - pointStart) / 1e9);
                    }
                }
            }
        } finally {
            pool.shutdownNow();
        }
        progress(results.size(), total, 0, null, t0);
        io.stderr().println();
        io.stderr().flush();
        SetupTimeChart.write(results, dir.resolve("setup-time.png"));
        String shape = SetupTimeShape.describe(results);
        Files.writeString(dir.resolve("shape.txt"), shape);
        io.stdout().print(shape);
        io.stdout().println("wrote " + dir.resolve("setup-time.csv") + ", " + dir.resolve("setup-time.png") + " and "
                + dir.resolve("shape.txt"));
        io.stdout().flush();
        return 0;
    }

    /** Deletes the generated missions (a 1,000-role point writes some 2,000 files), quietly: they are scratch. */
    private static void deleteTree(Path root) {
        try (Stream<Path> paths = Files.walk(root)) {
            paths.sorted(Comparator.reverseOrder()).forEach(p -> p.toFile().delete());
        } catch (IOException | UncheckedIOException e) {
            // left behind in the temporary directory; nothing depends on it
        }
    }

    /** A run's result and its diagnostic report (empty over UDP). */
    private record SimulatedRun(SetupResult result, String report) {
    }

    private SimulatedRun simulate(GeneratedMission g, Mission mission, Scheme scheme, int run, RadioNetwork radio,
                                  CpuCosts costs) {
        String[] report = {""};
        SetupResult r = SetupTimeRun.run(g, mission, scheme, run, seed + run, radio, costs, limitMillis, sparePercent,
                text -> report[0] = text);
        return new SimulatedRun(r, report[0]);
    }

    /** The run's outcome; a run that threw rethrows here, on the command's thread. */
    private static SimulatedRun outcome(Future<SimulatedRun> f) throws Exception {
        try {
            return f.get();
        } catch (ExecutionException e) {
            if (e.getCause() instanceof Exception cause) {
                throw cause;
            }
            throw e;
        }
    }

    /** Daemon threads, so a failing command never waits for the runs still going. */
    private static ThreadFactory runner() {
        AtomicInteger n = new AtomicInteger();
        return r -> {
            Thread t = new Thread(r, "setup-time-run-" + n.incrementAndGet());
            t.setDaemon(true);
            return t;
        };
    }

    private void verbose(int roles, Scheme scheme, int run, String report) {
        if (verbose) {
            io.stderr().print("\r");
            io.stdout().printf(Locale.ROOT, "%d roles %s run %d:%n%s", roles, scheme.name().toLowerCase(Locale.ROOT), run,
                    report.indent(2));
            io.stdout().flush();
        }
    }

    /** The most warm-up runs a point takes. */
    private static final int MAX_WARMUP = 1_000;

    /** The schemes asked for, each once, in the order first named ("both": distributed, centralised). */
    private List<Scheme> schemes() {
        Set<Scheme> set = new LinkedHashSet<>();
        for (String s : schemes) {
            switch (s.trim().toLowerCase(Locale.ROOT)) {
                case "distributed" -> set.add(Scheme.DISTRIBUTED);
                case "centralised", "centralized" -> set.add(Scheme.CENTRALISED);
                case "both" -> set.addAll(List.of(Scheme.DISTRIBUTED, Scheme.CENTRALISED));
                default -> throw new ParameterException(spec.commandLine(), "--schemes: unknown scheme '" + s
                        + "'; the schemes are distributed and centralised (both: the two)");
            }
        }
        return List.copyOf(set);
    }

    private void checkArguments() {
        if (runs < 1 || runs > MAX_RUNS) {
            throw new ParameterException(spec.commandLine(), "--runs " + runs + ": it must be 1 to " + MAX_RUNS);
        }
        if (jobs != null && jobs < 1) {
            throw new ParameterException(spec.commandLine(), "--jobs " + jobs + ": it must be 1 or more");
        }
        if (roles.isEmpty()) {
            throw new ParameterException(spec.commandLine(), "--roles: give at least one number of roles");
        }
        if (limitMillis < 1) {
            throw new ParameterException(spec.commandLine(), "--limit " + limitMillis + ": it must be 1 ms or more");
        }
        for (String t : transports) {
            if (!t.equals("sim") && !t.equals("udp")) {
                throw new ParameterException(spec.commandLine(), "--transport " + t + ": it must be sim, udp or sim,udp");
            }
        }
        transports = transports.stream().distinct().toList();
        if (sparePercent < 0 || sparePercent > GeneratedMission.MAX_SPARE_PERCENT) {
            throw new ParameterException(spec.commandLine(), "--spare " + sparePercent + ": it must be from 0 to "
                    + GeneratedMission.MAX_SPARE_PERCENT + " (percent of each role's seats)");
        }
        if (warmup < 0 || warmup > MAX_WARMUP) {
            throw new ParameterException(spec.commandLine(), "--warmup " + warmup + ": it must be from 0 to " + MAX_WARMUP);
        }
        if (warmup > 0 && !transports.contains("udp")) {
            throw new ParameterException(spec.commandLine(), "--warmup " + warmup + " without --transport udp: simulated "
                    + "runs charge measured costs of compiled code and take no warm-up");
        }
        if (sparePercent > 0 && transports.contains("udp")) {
            throw new ParameterException(spec.commandLine(), "--spare " + sparePercent + " with --transport udp: spare "
                    + "vehicles are for simulated runs; a run over UDP has one vehicle per seat");
        }
        if (transports.contains("udp")) {
            for (int n : roles) {
                if (n > UdpSetupTimeRun.MAX_ROLES) {
                    throw new ParameterException(spec.commandLine(), "--roles " + n + " with --transport udp: a run over "
                            + "UDP on one machine takes at most " + UdpSetupTimeRun.MAX_ROLES + " roles (each cell has "
                            + "threads and sockets of its own); give --roles of " + UdpSetupTimeRun.MAX_ROLES + " or fewer");
                }
            }
        }
    }

    private void progress(int done, int total, int roles, Scheme scheme, long t0) {
        progress(done, total, scheme == null ? "done" : roles + " roles, " + scheme.name().toLowerCase(Locale.ROOT), t0);
    }

    private void progress(int done, int total, String what, long t0) {
        int width = 30;
        int filled = total == 0 ? width : done * width / total;
        io.stderr().printf(Locale.ROOT, "\r[%s%s] %d/%d runs  %-28s %6.0f s", "#".repeat(filled),
                " ".repeat(width - filled), done, total, what, (System.nanoTime() - t0) / 1e9);
        io.stderr().flush();
    }

    /**
     * The logger property that sets the level of the communication manager's warnings (one per
     * critical message given up on), under the simple SLF4J binding the command runs with.
     */
    static final String COMM_LOG_LEVEL = "org.slf4j.simpleLogger.log.net.smc.core.comm.CommunicationManager";

    /**
     * A centralised commander of hundreds of roles is the bottleneck the experiment shows: its radio
     * backs up, Acks come too late, and its cells give up on thousands of critical messages a point,
     * each a warning that would bury the progress bar. The runs count them instead (the point's line
     * says how many); set {@link #COMM_LOG_LEVEL} to see each.
     */
    private static void quietUndeliveredWarnings() {
        if (System.getProperty(COMM_LOG_LEVEL) == null) {
            System.setProperty(COMM_LOG_LEVEL, "error");
        }
    }

    private void summary(List<SetupResult> results, int roles, Scheme scheme, String transport, double wallSeconds) {
        List<Double> times = new ArrayList<>();
        int incomplete = 0;
        long undelivered = 0;
        for (SetupResult r : results) {
            if (r.roles() == roles && r.scheme() == scheme && r.transport().equals(transport)) {
                undelivered += r.undelivered();
                if (r.complete()) {
                    times.add(r.setupMillis());
                } else {
                    incomplete++;
                }
            }
        }
        double[] v = SetupTimeChart.sortedCopy(times);
        io.stderr().print("\r");
        io.stdout().printf(Locale.ROOT, "%5d roles %-12s %-4s median %8.0f ms  p10 %8.0f  p90 %8.0f  (%d runs, %d incomplete, %s%.1f s wall)%n",
                roles, scheme.name().toLowerCase(Locale.ROOT), transport, v.length == 0 ? Double.NaN : SetupTimeChart.rank(v, 0.5),
                v.length == 0 ? Double.NaN : SetupTimeChart.rank(v, 0.1), v.length == 0 ? Double.NaN : SetupTimeChart.rank(v, 0.9),
                v.length, incomplete, undelivered == 0 ? "" : undelivered + " critical messages given up on, ", wallSeconds);
        io.stdout().flush();
    }
}
