package net.smc.sim.team;

import net.smc.core.host.CellHost;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.DatagramSocket;
import java.net.InetSocketAddress;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Collection;
import java.util.Deque;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.TreeMap;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Function;
import java.util.function.Predicate;

import net.smc.core.capability.CapabilityDescription;
import net.smc.core.cell.Cell;
import net.smc.core.cell.CellEvent;
import net.smc.core.host.CellHost;
import net.smc.core.cell.CellView;
import net.smc.core.cell.Missions;
import net.smc.core.mission.Mission;
import net.smc.core.transport.udp.UdpEventLoop;
import net.smc.core.transport.udp.UdpSettings;

/**
 * One team of {@link CellHost}s on loopback UDP, for scenario tests: the real-network counterpart
 * of {@code TeamSimulation}. Every cell binds its own unicast port on 127.0.0.1 and the team's own
 * broadcast port (so teams in one JVM cannot hear each other), on a shared {@link UdpEventLoop};
 * {@link LoopbackFaults} sit under each cell's authentication for loss and partitions.
 *
 * <p>Tests wait with {@link #await}: it polls every cell's view every {@value #POLL_MILLIS} ms,
 * checks the {@link ViewInvariants} on each round, and fails with the views and the end of the
 * trace when a rule breaks or the wait runs out. The wall clock is real: bounds are generous
 * liveness bounds, never timing claims.
 */
final class UdpTeam implements AutoCloseable {
    static final long POLL_MILLIS = 100;
    private static final int TRACE_LINES = 300;

    private final Mission mission;
    private final long seed;
    private final boolean secure;
    private final UdpEventLoop loop;
    private final LoopbackFaults faults;
    private final UdpSettings udp;
    private final long startMillis = System.currentTimeMillis();
    private final Map<String, CellHost> hosts = new LinkedHashMap<>();
    private final Map<String, CapabilityDescription> vehicles = new ConcurrentHashMap<>();
    private final Deque<String> trace = new ArrayDeque<>();

    /** @param secure whether cells authenticate (signed and MAC'd datagrams, credentials from one authority) */
    UdpTeam(Mission mission, long seed, boolean secure, UdpEventLoop loop) {
        this.mission = mission;
        this.seed = seed;
        this.secure = secure;
        this.loop = loop;
        this.faults = new LoopbackFaults();
        this.udp = UdpSettings.defaults().withBroadcast("127.255.255.255", freePort());
    }

    /** Starts the vehicles, the commander last: its first discovery finds every other cell listening. */
    void start(List<SimVehicle> team) {
        team.stream().filter(v -> !v.commander()).forEach(this::join);
        team.stream().filter(SimVehicle::commander).forEach(this::join);
    }

    /** Starts one vehicle's cell now. */
    synchronized void join(SimVehicle v) {
        if (hosts.containsKey(v.id())) {
            throw new IllegalArgumentException("vehicle '" + v.id() + "' is already in the team");
        }
        vehicles.put(v.id(), v.description());
        long cellSeed = seed * 1_000_003L + vehicles.size();
        CellHost.Settings s = CellHost.settings(v.id(), mission, v.description(), Missions.REPOSITORY)
                .udp(udp).commander(v.commander()).seed(cellSeed).trace(this::record)
                .wrap(faults.link(v.id(), cellSeed));
        if (secure) {
            s.security(SimIdentities.identity(v, mission.instanceName()), SimIdentities.trust(mission.instanceName()));
        }
        try {
            hosts.put(v.id(), CellHost.open(s, loop));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** Crashes a vehicle: its cell stops and its sockets close, without a word to anyone. */
    void crash(String vehicle) {
        CellHost host;
        synchronized (this) {
            host = hosts.remove(vehicle);
        }
        if (host == null) {
            throw new IllegalArgumentException("vehicle '" + vehicle + "' is not running");
        }
        record(new CellEvent(System.currentTimeMillis(), vehicle, CellEvent.Kind.LEFT, "*** crashed"));
        host.close();
    }

    /** Cuts {@code side} off from the rest of the team. */
    void partition(Collection<String> side) {
        faults.partition(side);
        record(new CellEvent(System.currentTimeMillis(), "-", CellEvent.Kind.LEFT, "*** partition " + side));
    }

    /** From now on, drops each arriving datagram with this probability. */
    void loss(double probability) {
        faults.loss(probability);
        record(new CellEvent(System.currentTimeMillis(), "-", CellEvent.Kind.LEFT, "*** loss " + probability));
    }

    void heal() {
        faults.heal();
        record(new CellEvent(System.currentTimeMillis(), "-", CellEvent.Kind.LEFT, "*** heal"));
    }

    /** Runs {@code action} on a vehicle's cell thread. */
    <T> T call(String vehicle, Function<Cell, T> action) {
        CellHost host;
        synchronized (this) {
            host = hosts.get(vehicle);
        }
        if (host == null) {
            throw new IllegalArgumentException("vehicle '" + vehicle + "' is not running");
        }
        return host.call(() -> action.apply(host.cell()));
    }

    /** The views of the running cells, by vehicle id, taken one after another. */
    Map<String, CellView> views() {
        List<Map.Entry<String, CellHost>> running;
        synchronized (this) {
            running = new ArrayList<>(hosts.entrySet());
        }
        Map<String, CellView> views = new TreeMap<>();
        running.forEach(e -> views.put(e.getKey(), e.getValue().view()));
        return views;
    }

    /**
     * Polls until {@code condition} holds of two rounds of views in a row, checking the invariants on
     * each round. A round is not an instant: views are read one cell after another, and under load a
     * cell's thread may answer a hundred milliseconds after the one before, so a seat handed from one
     * cell to another between the two reads shows in both. A rule therefore counts as broken, and a
     * condition as reached, only when two rounds in a row show it.
     *
     * @return the second round of views the condition held of
     * @throws AssertionError when an invariant breaks or {@code maxMillis} pass first
     */
    Map<String, CellView> await(String what, long maxMillis, Predicate<Map<String, CellView>> condition) {
        long end = System.nanoTime() + maxMillis * 1_000_000;
        Optional<String> brokenBefore = Optional.empty();
        boolean heldBefore = false;
        while (true) {
            Map<String, CellView> views = views();
            Optional<String> broken = ViewInvariants.violation(views, mission, vehicles);
            if (broken.isPresent() && broken.equals(brokenBefore)) {
                fail("invariant broken while waiting for " + what + ": " + broken.get() + report(views));
            }
            brokenBefore = broken;
            boolean held = broken.isEmpty() && condition.test(views);
            if (held && heldBefore) {
                return views;
            }
            heldBefore = held;
            if (System.nanoTime() > end && !held && broken.isEmpty()) {
                String unsettled = unsettled(views);
                fail(what + " not reached within " + maxMillis + " ms (" + (unsettled.isEmpty() ? "the team has settled"
                        : "not settled: " + unsettled) + ")" + report(views));
            }
            if (!held && broken.isEmpty()) {
                pause();
            }
        }
    }

    /** Lets {@code millis} pass, checking the invariants all along. */
    void hold(long millis) {
        long end = System.nanoTime() + millis * 1_000_000;
        await("the end of a " + millis + " ms hold", millis + 10 * POLL_MILLIS, views -> System.nanoTime() >= end);
    }

    /** Why the team has not settled on the best configuration its running vehicles allow (empty when it has). */
    String unsettled(Map<String, CellView> views) {
        return ViewInvariants.unsettled(views, mission, vehicles);
    }

    /** Whether a vehicle of the team meets the commander's requirement (and so may be a backup). */
    boolean ableToCommand(String vehicle) {
        CapabilityDescription d = vehicles.get(vehicle);
        return d != null && mission.role(Mission.COMMANDER).orElseThrow().requirement().isMetBy(d);
    }

    /** The acting commanders among running cells. */
    static List<String> commanders(Map<String, CellView> views) {
        return views.values().stream().filter(CellView::acting).map(CellView::vehicle).toList();
    }

    /** The acting commander a vehicle is attached to, if it is running and attached. */
    static Optional<String> root(Map<String, CellView> views, String vehicle) {
        CellView v = views.get(vehicle);
        return v == null ? Optional.empty() : ViewInvariants.root(v, views);
    }

    /** Whether a vehicle holds a seat of {@code role}. */
    static boolean holds(Map<String, CellView> views, String vehicle, String role) {
        CellView v = views.get(vehicle);
        return v != null && v.roles().stream().anyMatch(s -> ViewInvariants.seat(s).role().equals(role));
    }

    private String report(Map<String, CellView> views) {
        StringBuilder b = new StringBuilder("\nviews:");
        views.values().forEach(v -> b.append("\n  ").append(v.toJson()));
        b.append("\ntrace (ms since the team started):");
        synchronized (trace) {
            trace.forEach(line -> b.append('\n').append(line));
        }
        return b.toString();
    }

    private void record(CellEvent e) {
        String line = new CellEvent(e.timeMillis() - startMillis, e.vehicle(), e.kind(), e.detail()).toString();
        synchronized (trace) {
            if (trace.size() == TRACE_LINES) {
                trace.removeFirst();
            }
            trace.addLast(line);
        }
    }

    private static void pause() {
        try {
            Thread.sleep(POLL_MILLIS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted while waiting for the team", e);
        }
    }

    @Override
    public void close() {
        List<CellHost> running;
        synchronized (this) {
            running = new ArrayList<>(hosts.values());
            hosts.clear();
        }
        running.forEach(CellHost::close);
    }

    private static int freePort() {
        try (DatagramSocket probe = new DatagramSocket(new InetSocketAddress("0.0.0.0", 0))) {
            return probe.getLocalPort();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
