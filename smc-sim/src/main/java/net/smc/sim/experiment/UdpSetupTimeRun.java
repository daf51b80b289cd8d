package net.smc.sim.experiment;

import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.net.DatagramSocket;
import java.net.InetSocketAddress;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Objects;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Consumer;

import net.smc.core.cell.CellEvent;
import net.smc.core.cell.Scheme;
import net.smc.core.host.CellHost;
import net.smc.core.mission.Mission;
import net.smc.core.transport.udp.UdpSettings;
import net.smc.policy.api.PolicyRepository;
import net.smc.sim.team.CountingTransport;
import net.smc.sim.team.FreshIdentities;
import net.smc.sim.team.SimVehicle;

/**
 * One run of the set-up time experiment on the real network: the generated mission's whole team,
 * each vehicle a {@link CellHost} with its own threads (the cell's, its timer's, its UDP event
 * loop's) and its own sockets on loopback, all traffic signed and MAC'd with keys and credentials
 * made for the run ({@link FreshIdentities}). The set-up time is measured as {@link SetupTimeRun}
 * measures it, on the wall clock: from the commander's {@code COMMANDING} event until every seat's
 * vehicle reported {@code ACCEPTED}. The vehicles start first and the commander last, so every
 * cell listens when the commander first discovers. Nothing is charged or modelled: loopback has no
 * radio latency, and the cells share this machine's cores. The busiest cell's CPU time is that of
 * its thread (where datagrams are verified, decoded and acted on, and policies loaded) from its
 * cell's start (its boot policies loaded, as a simulated cell's are before its clock starts) until
 * the run was seen to end.
 *
 * <pre>{@code
 * SetupResult r = UdpSetupTimeRun.run(generated, mission, Scheme.DISTRIBUTED, 1, seed, 60_000);
 * }</pre>
 */
public final class UdpSetupTimeRun {
    /** The most roles a run on loopback takes: each cell has three threads of its own. */
    public static final int MAX_ROLES = 50;
    private static final long POLL_MILLIS = 20;
    private static final ThreadMXBean THREADS = ManagementFactory.getThreadMXBean();

    private UdpSetupTimeRun() {
    }

    /**
     * Runs one team until every role started or {@code limitMillis} of wall time passed.
     *
     * @param mission the generated mission loaded for {@code scheme}
     * @throws IllegalArgumentException when the mission has more than {@link #MAX_ROLES} roles
     * @throws IOException              when a cell cannot bind its sockets
     */
    public static SetupResult run(GeneratedMission generated, Mission mission, Scheme scheme, int run, long seed,
                                  long limitMillis) throws IOException {
        Objects.requireNonNull(scheme, "scheme");
        if (generated.seats() > MAX_ROLES) {
            throw new IllegalArgumentException("a set-up over UDP takes at most " + MAX_ROLES + " roles (three threads"
                    + " and two sockets per cell on one machine); this mission has " + generated.seats());
        }
        if (limitMillis <= 0) {
            throw new IllegalArgumentException("time limit " + limitMillis + " ms must be above 0");
        }
        long now = System.currentTimeMillis();
        FreshIdentities ids = new FreshIdentities(mission.instanceName(), now - 60_000, now + TimeUnit.DAYS.toMillis(1));
        PolicyRepository repository = new PolicyRepository(generated.repository());
        UdpSettings udp = UdpSettings.defaults().withBroadcast("127.255.255.255", freePort());
        AtomicLong datagrams = new AtomicLong();
        AtomicLong bytes = new AtomicLong();
        Progress progress = new Progress(generated.seats() - 1, datagrams, bytes);
        List<SimVehicle> team = new ArrayList<>(generated.vehicles());
        team.sort((a, b) -> Boolean.compare(a.commander(), b.commander()));   // the commander last
        List<CellHost> hosts = new ArrayList<>();
        try {
            int n = 0;
            long[] startCpu = new long[team.size()];
            for (SimVehicle v : team) {
                int at = n;
                CellHost.Settings s = CellHost.settings(v.id(), mission, v.description(), repository)
                        .beforeStart(c -> startCpu[at] = THREADS.getCurrentThreadCpuTime())
                        .udp(udp).commander(v.commander()).scheme(scheme).seed(seed * 1_000_003L + n++)
                        .security(ids.identity(v.id()), ids.trust()).trace(progress)
                        .wrap(t -> new CountingTransport(t, datagrams, bytes));
                hosts.add(CellHost.open(s));
            }
            long end = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(limitMillis);
            while (!progress.complete() && System.nanoTime() < end) {
                Thread.sleep(POLL_MILLIS);
            }
            for (int i = 0; i < hosts.size(); i++) {
                long atStart = startCpu[i];
                CellHost host = hosts.get(i);
                progress.cpu(host.call(() -> THREADS.getCurrentThreadCpuTime() - atStart));
                progress.undelivered(host.call(() -> host.cell().communication().sender().counters().failed()));
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted while waiting for the team to set up", e);
        } finally {
            hosts.forEach(CellHost::close);
        }
        return progress.result(generated.seats(), scheme, run);
    }

    /** Follows the cells' events (from their threads): the commander's start and each seat's first acceptance. */
    private static final class Progress implements Consumer<CellEvent> {
        private final Set<String> seats = new HashSet<>();
        private final int needed;
        private final AtomicLong datagrams;
        private final AtomicLong bytes;
        private long startNanos = -1;
        private long endNanos = -1;
        private long messages = -1;
        private long sentBytes = -1;
        private long busiestCpuNanos;
        private long undelivered;

        Progress(int needed, AtomicLong datagrams, AtomicLong bytes) {
            this.needed = needed;
            this.datagrams = datagrams;
            this.bytes = bytes;
        }

        @Override
        public synchronized void accept(CellEvent e) {
            long at = System.nanoTime();
            if (e.kind() == CellEvent.Kind.COMMANDING && e.vehicle().equals(GeneratedMission.COMMANDER) && startNanos < 0) {
                startNanos = at;
            } else if (e.kind() == CellEvent.Kind.ACCEPTED && endNanos < 0) {
                int space = e.detail().indexOf(' ');
                if (seats.add(space < 0 ? e.detail() : e.detail().substring(0, space)) && seats.size() == needed) {
                    endNanos = at;
                    messages = datagrams.get();
                    sentBytes = bytes.get();
                }
            }
        }

        /** A cell thread's CPU time so far, ns (-1 when the JVM does not measure it). */
        synchronized void cpu(long nanos) {
            busiestCpuNanos = Math.max(busiestCpuNanos, nanos);
        }

        synchronized void undelivered(long failed) {
            undelivered += failed;
        }

        synchronized boolean complete() {
            return seats.size() >= needed;
        }

        synchronized SetupResult result(int roles, Scheme scheme, int run) {
            boolean done = complete() && startNanos >= 0;
            double setup = done ? (endNanos - startNanos) / 1e6 : -1;
            return new SetupResult(roles, scheme, "udp", run, setup, done ? messages : datagrams.get(),
                    done ? sentBytes : bytes.get(), busiestCpuNanos / 1e6, seats.size(), undelivered);
        }
    }

    private static int freePort() throws IOException {
        try (DatagramSocket probe = new DatagramSocket(new InetSocketAddress("0.0.0.0", 0))) {
            return probe.getLocalPort();
        }
    }
}
