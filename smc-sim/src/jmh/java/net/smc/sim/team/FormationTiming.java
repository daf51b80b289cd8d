package net.smc.sim.team;

import net.smc.core.host.CellHost;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.DatagramSocket;
import java.net.InetSocketAddress;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.OptionalDouble;
import java.util.function.Predicate;

import net.smc.core.cell.CellEvent;
import net.smc.core.host.CellHost;
import net.smc.core.mission.Mission;
import net.smc.core.mission.MissionLoader;
import net.smc.core.transport.udp.UdpEventLoop;
import net.smc.core.transport.udp.UdpSettings;
import net.smc.policy.api.PolicyRepository;

/**
 * How long the reconnaissance team takes to form and to recover from failures, under both schemes
 * (missions {@code reconnaissance.instance.xml} and {@code reconnaissance-centralised.instance.xml}:
 * comTimeout 500 ms, failureTimeout 3 s, one backup), and how fast the simulation runs. Prints
 * tables of minimum, median, 90th percentile (nearest rank) and maximum, in ms:
 * <ul>
 *   <li>the commander's start (its COMMANDING event; its first discovery goes out at its first
 *       tick, a random phase of 0 to comTimeout later, which the figures include) to the minimal
 *       configuration (mission state RUNNING or better) and to the reasonably-optimal one (OPTIMAL),
 *       for the 8-vehicle team (commander, 2 surveyors, aggregator, 2 detectors, 2 relays); on the
 *       simulated network also for its first 4, with the other 4 joining once the mission runs;</li>
 *   <li>a surveyor's crash (a spare surveyor present) to another vehicle accepting its seat, and to
 *       the commander reporting OPTIMAL again;</li>
 *   <li>the commander's crash to its backup taking over.</li>
 * </ul>
 * Each measurement runs on the <b>simulated network</b> ({@link TeamSimulation}: 5 ms latency plus
 * up to 10 ms jitter, no loss, ideal authentication; simulated time; one run per seed) and on
 * <b>UDP loopback</b> (a {@link CellHost} per vehicle on one shared Netty event loop, no
 * authentication; wall time, taken when a cell reports the event on its thread). Last, the
 * <b>simulation speed</b>: simulated seconds per wall second for the 8-vehicle team and for 200
 * vehicles (the 8 and 192 spares: the mission has 8 seats), with the invariants checked every step.
 *
 * <pre>./gradlew :smc-core:jmh -PjmhMain=net.smc.core.cell.FormationTiming -PjmhArgs="200 5"</pre>
 * (arguments: simulated seeds (200), loopback runs per crash measurement (5), project directory (..))
 *
 * <p>Measured on a 2-core VM (200 seeds, 5 loopback runs), median (90th percentile), distributed /
 * centralised: the 8-vehicle team forms in 1.16 s (1.41 s) / 0.31 s (0.52 s) simulated and 1.09 s
 * (1.40 s) / 0.28 s (0.51 s) on loopback; the commander's view goes from FORMING straight to OPTIMAL
 * when all 8 start together, so RUNNING and OPTIMAL coincide. A spare takes a crashed surveyor's seat
 * after 3.2 s (3.5 s) / 2.9 s (3.4 s), and the backup takes over 3.9 s (4.0 s) / 3.7 s (3.9 s) after
 * the commander's crash; loopback is within half a second of these. The simulation runs the
 * 8-vehicle team at about 2,100 to 2,900 simulated seconds per wall second and 200 vehicles at about
 * 220 on an otherwise idle machine, a third of that or less while other builds share its two cores.
 */
public final class FormationTiming {
    private static final String CDR = "cdr";
    private static final long LIMIT_MILLIS = 60_000;

    private final PolicyRepository repository;
    private final Map<String, Mission> missions = new LinkedHashMap<>();

    private FormationTiming(Path project) throws Exception {
        this.repository = new PolicyRepository(project.resolve("policies"));
        MissionLoader loader = new MissionLoader(repository);
        missions.put("distributed", loader.load(project.resolve("missions/reconnaissance.instance.xml")));
        missions.put("centralised", loader.load(project.resolve("missions/reconnaissance-centralised.instance.xml")));
    }

    public static void main(String[] args) throws Exception {
        int seeds = args.length > 0 ? Integer.parseInt(args[0]) : 200;
        int runs = args.length > 1 ? Integer.parseInt(args[1]) : 5;
        Path project = Path.of(args.length > 2 ? args[2] : "..");
        FormationTiming timing = new FormationTiming(project);
        timing.simulated(seeds);
        timing.loopback(runs);
        timing.speed();
    }

    // ------------------------------------------------------------------ the measurements

    /** The 8-vehicle team forms. */
    private static void formation(Team team, Samples running, Samples optimal) {
        team.until(Events.OPTIMAL, 0);
        double start = team.events().first(Events.START, 0).orElse(Double.NaN);
        running.add(team.events().first(Events.RUNNING, 0), start);
        optimal.add(team.events().first(Events.OPTIMAL, 0), start);
    }

    /** The first 4 vehicles form the minimal configuration; 4 more join then. */
    private static void growth(Team team, Samples running, Samples grown) {
        team.until(Events.RUNNING, 0);
        double start = team.events().first(Events.START, 0).orElse(Double.NaN);
        running.add(team.events().first(Events.RUNNING, 0), start);
        double joined = team.now();
        for (SimVehicle v : List.of(SimVehicle.detector("d1"), SimVehicle.detector("d2"), SimVehicle.relay("r1"),
                SimVehicle.relay("r2"))) {
            team.join(v);
        }
        team.until(Events.OPTIMAL, joined);
        grown.add(team.events().first(Events.OPTIMAL, joined), joined);
    }

    /** After formation, a spare surveyor joins and surveyor s1 crashes 2 s later. */
    private static void surveyorCrash(Team team, Samples replaced, Samples whole) {
        team.join(SimVehicle.surveyor("s3"));
        team.pass(2_000);
        double crashed = team.now();
        team.crash("s1");
        Predicate<CellEvent> replacement = Events.surveyorTakenBy(v -> !v.equals("s1"));
        team.until(replacement, crashed);
        replaced.add(team.events().first(replacement, crashed), crashed);
        team.until(Events.NOT_OPTIMAL, crashed);
        double degraded = team.events().first(Events.NOT_OPTIMAL, crashed).orElse(crashed);
        team.until(Events.OPTIMAL, degraded);
        whole.add(team.events().first(Events.OPTIMAL, degraded), crashed);
    }

    /** After formation, the commander crashes 3 s later (the roster has reached the backup). */
    private static void commanderCrash(Team team, Samples tookOver) {
        team.pass(3_000);
        double crashed = team.now();
        team.crash(CDR);
        team.until(Events.TOOK_OVER, crashed);
        tookOver.add(team.events().first(Events.TOOK_OVER, crashed), crashed);
    }

    // ------------------------------------------------------------------ simulated network

    private void simulated(int seeds) {
        Table table = new Table("Simulated network, " + seeds + " seeds (one run each), simulated ms");
        for (Map.Entry<String, Mission> m : missions.entrySet()) {
            Mission mission = m.getValue();
            Samples running = new Samples();
            Samples optimal = new Samples();
            Samples fewRunning = new Samples();
            Samples grown = new Samples();
            Samples replaced = new Samples();
            Samples whole = new Samples();
            Samples tookOver = new Samples();
            for (long seed = 1; seed <= seeds; seed++) {
                formation(new Sim(mission, seed, SimVehicle.reconnaissance(2, 1, 2, 2)), running, optimal);
                growth(new Sim(mission, seed, SimVehicle.reconnaissance(2, 1, 0, 0)), fewRunning, grown);
                Sim surveyor = new Sim(mission, seed, SimVehicle.reconnaissance(2, 1, 2, 2));
                formation(surveyor, new Samples(), new Samples());
                surveyorCrash(surveyor, replaced, whole);
                Sim commander = new Sim(mission, seed, SimVehicle.reconnaissance(2, 1, 2, 2));
                formation(commander, new Samples(), new Samples());
                commanderCrash(commander, tookOver);
            }
            String scheme = m.getKey();
            table.row("8 vehicles: commander start -> RUNNING", scheme, running);
            table.row("8 vehicles: commander start -> OPTIMAL", scheme, optimal);
            table.row("4 vehicles: commander start -> RUNNING", scheme, fewRunning);
            table.row("4 more join at RUNNING: join -> OPTIMAL", scheme, grown);
            table.row("surveyor crash -> spare ACCEPTED its seat", scheme, replaced);
            table.row("surveyor crash -> OPTIMAL again", scheme, whole);
            table.row("commander crash -> backup TOOK_OVER", scheme, tookOver);
        }
        table.print();
    }

    // ------------------------------------------------------------------ UDP loopback

    private void loopback(int runs) {
        Table table = new Table("UDP loopback, " + runs + " runs per crash measurement (formation: every run), wall ms");
        try (UdpEventLoop loop = UdpEventLoop.create(1)) {
            for (Map.Entry<String, Mission> m : missions.entrySet()) {
                Samples running = new Samples();
                Samples optimal = new Samples();
                Samples replaced = new Samples();
                Samples whole = new Samples();
                Samples tookOver = new Samples();
                for (int run = 1; run <= runs; run++) {
                    try (Loopback team = new Loopback(m.getValue(), run, loop)) {
                        formation(team, running, optimal);
                        surveyorCrash(team, replaced, whole);
                    }
                    try (Loopback team = new Loopback(m.getValue(), 1_000 + run, loop)) {
                        formation(team, running, optimal);
                        commanderCrash(team, tookOver);
                    }
                }
                String scheme = m.getKey();
                table.row("8 vehicles: commander start -> RUNNING", scheme, running);
                table.row("8 vehicles: commander start -> OPTIMAL", scheme, optimal);
                table.row("surveyor crash -> spare ACCEPTED its seat", scheme, replaced);
                table.row("surveyor crash -> OPTIMAL again", scheme, whole);
                table.row("commander crash -> backup TOOK_OVER", scheme, tookOver);
            }
        }
        table.print();
    }

    // ------------------------------------------------------------------ simulation speed

    private void speed() {
        System.out.println("Simulation speed (simulated s per wall s; invariants checked every 50 ms step; "
                + "the first run of each row warms the JIT and is not counted)");
        System.out.printf(Locale.ROOT, "%-48s %-12s %10s %9s %8s%n", "team", "scheme", "simulated", "wall", "ratio");
        for (Map.Entry<String, Mission> m : missions.entrySet()) {
            speedRow("8 vehicles, formation + 600 s", m.getKey(), m.getValue(), SimVehicle.reconnaissance(2, 1, 2, 2),
                    600_000);
        }
        List<SimVehicle> many = new ArrayList<>(SimVehicle.reconnaissance(2, 1, 2, 2));
        for (int i = 1; many.size() < 200; i++) {
            many.add(switch (i % 4) {
                case 0 -> SimVehicle.surveyor("xs" + i);
                case 1 -> SimVehicle.detector("xd" + i);
                case 2 -> SimVehicle.relay("xr" + i);
                default -> SimVehicle.aggregator("xa" + i);
            });
        }
        for (Map.Entry<String, Mission> m : missions.entrySet()) {
            speedRow("200 vehicles (8 + 192 spares), formation + 60 s", m.getKey(), m.getValue(), many, 60_000);
        }
        System.out.println();
    }

    private void speedRow(String name, String scheme, Mission mission, List<SimVehicle> vehicles, long steadyMillis) {
        Sim warm = new Sim(mission, 1, vehicles);
        warm.until(Events.OPTIMAL, 0);
        warm.pass(steadyMillis / 10);
        long t0 = System.nanoTime();
        Sim sim = new Sim(mission, 2, vehicles);
        sim.until(Events.OPTIMAL, 0);
        sim.pass(steadyMillis);
        double wall = (System.nanoTime() - t0) / 1e9;
        double simulated = sim.now() / 1e3;
        OptionalDouble optimal = sim.events().first(Events.OPTIMAL, 0);
        System.out.printf(Locale.ROOT, "%-48s %-12s %9.0fs %8.2fs %8.0f   (OPTIMAL at %s)%n", name, scheme, simulated,
                wall, simulated / wall, optimal.isPresent() ? String.format(Locale.ROOT, "%.0f ms", optimal.getAsDouble())
                        : "never");
    }

    // ------------------------------------------------------------------ the two kinds of team

    /** A team the measurements run on; times are ms on its own clock. */
    private interface Team {
        Events events();

        /** The time now. */
        double now();

        /** Lets time pass until an event matching {@code p} at or after {@code after} is seen, or the limit passes. */
        void until(Predicate<CellEvent> p, double after);

        /** Lets {@code millis} pass. */
        void pass(long millis);

        void join(SimVehicle vehicle);

        void crash(String vehicle);
    }

    /** A team on the simulated network; time is the simulation's. */
    private final class Sim implements Team {
        private final TeamSimulation sim;
        private final Events events = new Events(true);

        Sim(Mission mission, long seed, List<SimVehicle> vehicles) {
            this.sim = TeamSimulation.builder(mission, repository, seed).vehicles(vehicles).listener(events).build();
            sim.start();
        }

        @Override
        public Events events() {
            return events;
        }

        @Override
        public double now() {
            return sim.nowMillis();
        }

        @Override
        public void until(Predicate<CellEvent> p, double after) {
            sim.runUntil(() -> events.first(p, after).isPresent(), LIMIT_MILLIS);
        }

        @Override
        public void pass(long millis) {
            sim.run(millis);
        }

        @Override
        public void join(SimVehicle vehicle) {
            sim.join(vehicle);
        }

        @Override
        public void crash(String vehicle) {
            sim.crash(vehicle);
        }
    }

    /**
     * The 8-vehicle team on loopback UDP: a unicast port each on 127.0.0.1, one broadcast port of its
     * own; the commander starts last, so its first discovery finds every other cell listening. A
     * crash closes the vehicle's host. Time is the wall clock.
     */
    private final class Loopback implements Team, AutoCloseable {
        private final Mission mission;
        private final long seed;
        private final UdpEventLoop loop;
        private final UdpSettings udp = UdpSettings.defaults().withBroadcast("127.255.255.255", freePort());
        private final Events events = new Events(false);
        private final Map<String, CellHost> hosts = new LinkedHashMap<>();

        Loopback(Mission mission, long seed, UdpEventLoop loop) {
            this.mission = mission;
            this.seed = seed;
            this.loop = loop;
            List<SimVehicle> team = new ArrayList<>(SimVehicle.reconnaissance(2, 1, 2, 2));
            team.add(team.remove(0));
            team.forEach(this::join);
        }

        @Override
        public Events events() {
            return events;
        }

        @Override
        public double now() {
            return Events.wallMillis();
        }

        @Override
        public void until(Predicate<CellEvent> p, double after) {
            long end = System.nanoTime() + LIMIT_MILLIS * 1_000_000;
            while (events.first(p, after).isEmpty() && System.nanoTime() < end) {
                pass(5);
            }
        }

        @Override
        public void pass(long millis) {
            try {
                Thread.sleep(millis);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new IllegalStateException("interrupted", e);
            }
        }

        @Override
        public void join(SimVehicle v) {
            try {
                hosts.put(v.id(), CellHost.open(CellHost.settings(v.id(), mission, v.description(), repository)
                        .udp(udp).commander(v.commander()).seed(seed * 31 + hosts.size()).trace(events), loop));
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
        }

        @Override
        public void crash(String vehicle) {
            hosts.remove(vehicle).close();
        }

        @Override
        public void close() {
            hosts.values().forEach(CellHost::close);
        }
    }

    private static int freePort() {
        try (DatagramSocket probe = new DatagramSocket(new InetSocketAddress("0.0.0.0", 0))) {
            return probe.getLocalPort();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    // ------------------------------------------------------------------ events and figures

    /**
     * The events of one team with the time each was seen (ms): the event's own time on the simulated
     * clock, or the wall clock ({@link System#nanoTime()}) when the cell reported it, on its own thread.
     */
    private static final class Events implements java.util.function.Consumer<CellEvent> {
        static final Predicate<CellEvent> START = e -> e.vehicle().equals(CDR) && e.kind() == CellEvent.Kind.COMMANDING;
        static final Predicate<CellEvent> RUNNING = state("RUNNING").or(state("OPTIMAL"));
        static final Predicate<CellEvent> OPTIMAL = state("OPTIMAL");
        static final Predicate<CellEvent> NOT_OPTIMAL = state("RUNNING").or(state("FORMING"));
        static final Predicate<CellEvent> TOOK_OVER = e -> e.kind() == CellEvent.Kind.TOOK_OVER;

        private final boolean simulated;
        private final List<Double> times = new ArrayList<>();
        private final List<CellEvent> list = new ArrayList<>();

        Events(boolean simulated) {
            this.simulated = simulated;
        }

        static double wallMillis() {
            return System.nanoTime() / 1e6;
        }

        /** The commander's view of the mission changed to {@code name}. */
        static Predicate<CellEvent> state(String name) {
            return e -> e.kind() == CellEvent.Kind.MISSION_STATE && e.detail().startsWith(name + " ");
        }

        /** A vehicle that {@code who} accepts accepted a surveyor seat. */
        static Predicate<CellEvent> surveyorTakenBy(Predicate<String> who) {
            return e -> e.kind() == CellEvent.Kind.ACCEPTED && e.detail().startsWith("surveyor#") && who.test(e.vehicle());
        }

        @Override
        public synchronized void accept(CellEvent e) {
            list.add(e);
            times.add(simulated ? e.timeMillis() : wallMillis());
        }

        /** When the first event matching {@code p} at or after {@code after} was seen. */
        synchronized OptionalDouble first(Predicate<CellEvent> p, double after) {
            for (int i = 0; i < list.size(); i++) {
                double t = times.get(i);
                if (t >= after && p.test(list.get(i))) {
                    return OptionalDouble.of(t);
                }
            }
            return OptionalDouble.empty();
        }
    }

    /** Durations of one measurement (ms), and how many runs never got there within the limit. */
    private static final class Samples {
        private final List<Double> values = new ArrayList<>();
        private int missed;

        void add(OptionalDouble end, double start) {
            if (end.isPresent() && !Double.isNaN(start)) {
                values.add(end.getAsDouble() - start);
            } else {
                missed++;
            }
        }

        String format() {
            double[] v = values.stream().mapToDouble(Double::doubleValue).sorted().toArray();
            if (v.length == 0) {
                return String.format(Locale.ROOT, "%5d %8s %8s %8s %8s %6d", 0, "-", "-", "-", "-", missed);
            }
            return String.format(Locale.ROOT, "%5d %8.0f %8.0f %8.0f %8.0f %6d", v.length, v[0], rank(v, 0.5),
                    rank(v, 0.9), v[v.length - 1], missed);
        }

        private static double rank(double[] sorted, double q) {
            int i = (int) Math.ceil(q * sorted.length) - 1;
            return sorted[Math.max(0, Math.min(sorted.length - 1, i))];
        }
    }

    private static final class Table {
        private final String title;
        private final List<String> rows = new ArrayList<>();

        Table(String title) {
            this.title = title;
        }

        void row(String measurement, String scheme, Samples samples) {
            rows.add(String.format(Locale.ROOT, "%-44s %-12s %s", measurement, scheme, samples.format()));
        }

        void print() {
            System.out.println(title);
            System.out.printf(Locale.ROOT, "%-44s %-12s %5s %8s %8s %8s %8s %6s%n", "measurement", "scheme", "n", "min",
                    "median", "p90", "max", "missed");
            rows.forEach(System.out::println);
            System.out.println();
            System.out.flush();
        }
    }
}
