package net.smc.sim.team;

import java.io.IOException;
import java.net.DatagramSocket;
import java.net.InetSocketAddress;
import java.util.Collection;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.ReentrantLock;
import java.util.function.BooleanSupplier;
import java.util.function.Supplier;

import net.smc.core.cell.Cell;
import net.smc.core.host.CellHost;
import net.smc.core.role.TaskProvider;
import net.smc.core.transport.Address;
import net.smc.core.transport.Clock;
import net.smc.core.transport.ForwardingTransport;
import net.smc.core.transport.Receiver;
import net.smc.core.transport.Transport;
import net.smc.core.transport.sim.SimulationScheduler;
import net.smc.core.transport.udp.UdpCounters;
import net.smc.core.transport.udp.UdpSettings;
import net.smc.sim.radio.WorldRadio;
import net.smc.sim.world.SimWorld;

/**
 * A team in a simulated world whose cells run on the real network: every vehicle is a
 * {@link CellHost} with its own threads and its own Netty UDP sockets on loopback, its traffic
 * signed and MAC'd by the real {@code SecureTransport} with keys and credentials made for the run
 * ({@link FreshIdentities}); the world stays in this process and is stepped on a thread of its own.
 *
 * <p><b>Time.</b> One mission clock, started by {@link #start} once every cell is up, runs {@code speed} times as fast
 * as the wall clock; the cells read it and their timers wait on it ({@code CellHost.Settings#clock}),
 * and the world thread steps the world's virtual clock up to it every few milliseconds. At speed 1
 * the mission runs in real time.
 *
 * <p><b>Threads.</b> One lock serialises the world's steps and every input of every cell (each
 * host's guard): a task's control loop, run by a world step, may raise an event into its cell's
 * policy engine, and a cell's policies call its tasks, which drive the robot. So the world, the
 * tasks and the cells' engines are only ever touched by one thread at a time, and the cells still
 * run on their own threads, between world steps. The price: the cells' work (Ed25519 signatures
 * and verifications above all) and the world's steps add up on one lock, so together they must
 * fit in one core at the chosen speed; about 2 mission seconds per wall second on a loaded
 * 2-core machine.
 *
 * <p><b>Radio.</b> Under each cell's authentication a filter asks the world's radio, for every
 * datagram that arrives, whether the sender reaches this vehicle now (a robot whose radio the
 * hazard broke reaches no one), and drops it if not, or with the link profile's loss probability.
 *
 * <p>Built from the same {@link TeamSimulationBuilder} as a simulation ({@link #open}); the link's
 * latency is ignored (loopback has its own), security is always real.
 */
public final class LiveTeam implements CellTeam {
    /** Wall time between two world-thread rounds at most, ms. */
    private static final long WORLD_POLL_MILLIS = 5;
    private static final long WAIT_POLL_MILLIS = 10;

    private final TeamSimulationBuilder spec;
    private final double speed;
    private final ReentrantLock lock = new ReentrantLock(true);
    private final MissionClock clock;
    private final SimulationScheduler worldTime = new SimulationScheduler();
    private final WorldTeam world;
    private final FreshIdentities identities;
    private final UdpSettings udp;
    private final Map<String, SimVehicle> vehicles = new LinkedHashMap<>();
    private final Map<String, Address> addresses = new LinkedHashMap<>();
    private final Map<String, CellHost> hosts = new LinkedHashMap<>();
    private volatile boolean running;
    private Thread worldThread;
    private volatile RuntimeException worldFailure;

    private LiveTeam(TeamSimulationBuilder b, double speed) throws IOException {
        if (b.arena == null) {
            throw new IllegalArgumentException("a live team needs a world (TeamSimulationBuilder.world)");
        }
        if (!(speed > 0) || speed > 100) {
            throw new IllegalArgumentException("speed " + speed + " is out of range; it must be above 0 and at most 100"
                    + " mission seconds per wall second");
        }
        this.spec = b;
        this.speed = speed;
        this.clock = new MissionClock(speed);
        this.identities = new FreshIdentities(b.mission.instanceName(), 0, TimeUnit.DAYS.toMillis(365));
        this.udp = UdpSettings.defaults().withBroadcast("127.255.255.255", freePort());
        this.world = new WorldTeam(this, SimWorld.builder(b.arena, worldTime).seed(b.seed).radio(b.radio).robotSpec(b.robotSpec).build(), b.catalog,
                b.places, b.standalone);
        for (SimVehicle v : b.vehicles) {
            if (vehicles.put(v.id(), v) != null) {
                throw new IllegalArgumentException("vehicle '" + v.id() + "' is in the team twice");
            }
            Address a = Address.of(udp.reachableHost(), freePort());
            addresses.put(v.id(), a);
            world.bind(v.id(), a);
        }
        world.checkPlaces(vehicles.keySet(), java.util.Set.of());   // no vehicle joins a live team later
    }

    /**
     * A live team with the vehicles, world, places, tasks, listener and output of {@code b}, its
     * mission clock at {@code speed} mission seconds per wall second (above 0, at most 100).
     *
     * @throws IOException when no free port can be found
     */
    public static LiveTeam open(TeamSimulationBuilder b, double speed) throws IOException {
        return new LiveTeam(b, speed);
    }

    /**
     * Starts the cells, the commander last so that every cell listens when it first discovers, then
     * the mission clock and the world's thread. The clock reads 0 until every cell is up: opening
     * sockets and loading the first policies takes a while, which a mission that starts at once
     * (as in simulation) does not count.
     */
    @Override
    public void start() {
        if (running) {
            return;
        }
        running = true;
        exclusive(() -> {
            world.start();
            return null;
        });
        vehicles.values().stream().filter(v -> !v.commander()).forEach(this::boot);
        vehicles.values().stream().filter(SimVehicle::commander).forEach(this::boot);
        clock.start();
        worldThread = new Thread(this::stepWorld, "world");
        worldThread.setDaemon(true);
        worldThread.start();
    }

    private void boot(SimVehicle v) {
        String id = v.id();
        int n = List.copyOf(vehicles.keySet()).indexOf(id);
        TaskProvider provider = exclusive(() -> world.tasks(id));
        CellHost.Settings s = CellHost.settings(id, spec.mission, world.describe(v), spec.repository)
                .udp(udp.withPort(addresses.get(id).port())).commander(v.commander()).seed(spec.seed * 1_000_003L + n)
                .security(identities.identity(id), identities.trust()).clock(clock, speed).guard(lock)
                .auth(spec.auth).tasks(provider).trace(spec.listener)
                .output(line -> spec.output.accept(id, line))
                .wrap(t -> new RadioFilter(t, addresses.get(id), world.world().radio(),
                        spec.link.lossProbability(), spec.seed * 31 + n))
                .beforeStart(c -> world.install(id, c))
                .afterStart(c -> world.booted(id, c, provider));
        if (spec.scheme != null) {
            s.scheme(spec.scheme);
        }
        try {
            CellHost host = CellHost.open(s);
            synchronized (hosts) {
                hosts.put(id, host);
            }
        } catch (IOException e) {
            throw new IllegalStateException("vehicle '" + id + "' cannot open its UDP sockets at "
                    + addresses.get(id) + ": " + e.getMessage(), e);
        }
    }

    /** The world thread: steps the world's clock up to the mission clock, round after round. */
    private void stepWorld() {
        long pause = Math.max(1, Math.min(WORLD_POLL_MILLIS, Math.round(world.world().stepMillis() / speed / 2)));
        try {
            while (running) {
                long target = clock.nowMillis();
                lock.lock();
                try {
                    if (running) {
                        worldTime.runUntil(target);
                    }
                } finally {
                    lock.unlock();
                }
                Thread.sleep(pause);
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (RuntimeException e) {
            worldFailure = e;
        }
    }

    @Override
    public long nowMillis() {
        return clock.nowMillis();
    }

    /** Waits (polling on the caller's thread) until {@code condition} holds or {@code maxMillis} of mission time passed. */
    @Override
    public boolean runUntil(BooleanSupplier condition, long maxMillis) {
        long end = clock.nowMillis() + maxMillis;
        while (true) {
            if (worldFailure != null) {
                throw new IllegalStateException("the world's thread failed: " + worldFailure.getMessage(), worldFailure);
            }
            if (exclusive(condition::getAsBoolean)) {
                return true;
            }
            if (clock.nowMillis() >= end) {
                return false;
            }
            try {
                Thread.sleep(WAIT_POLL_MILLIS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new IllegalStateException("interrupted while the team ran", e);
            }
        }
    }

    @Override
    public <T> T exclusive(Supplier<T> action) {
        lock.lock();
        try {
            return action.get();
        } finally {
            lock.unlock();
        }
    }

    @Override
    public Cell cell(String vehicle) {
        CellHost h;
        synchronized (hosts) {
            h = hosts.get(vehicle);
        }
        return h == null ? null : h.cell();
    }

    @Override
    public Collection<SimVehicle> vehicles() {
        return List.copyOf(vehicles.values());
    }

    @Override
    public SimVehicle vehicle(String id) {
        SimVehicle v = vehicles.get(id);
        if (v == null) {
            throw new IllegalArgumentException("no vehicle '" + id + "' in the team");
        }
        return v;
    }

    @Override
    public boolean isLive(String vehicle) {
        synchronized (hosts) {
            return running && hosts.containsKey(vehicle);
        }
    }

    @Override
    public Address address(String vehicle) {
        Address a = addresses.get(vehicle);
        if (a == null) {
            throw new IllegalArgumentException("no vehicle '" + vehicle + "' in the team");
        }
        return a;
    }

    @Override
    public WorldTeam world() {
        return world;
    }

    @Override
    public SimulationScheduler scheduler() {
        return worldTime;
    }

    /** Mission seconds per wall second. */
    public double speed() {
        return speed;
    }

    /** What every cell's UDP sockets did so far, added up (datagrams handed to the kernel, delivered ...). */
    public UdpCounters udpCounters() {
        List<CellHost> open;
        synchronized (hosts) {
            open = List.copyOf(hosts.values());
        }
        long[] t = new long[11];
        for (CellHost h : open) {
            UdpCounters c = h.udpCounters();
            long[] v = {c.sent(), c.broadcastsSent(), c.sendFailures(), c.refusedOversize(), c.delivered(),
                c.ownBroadcastsFiltered(), c.droppedOversize(), c.droppedNoReceiver(), c.droppedClosed(),
                c.droppedRejected(), c.droppedBacklog()};
            for (int i = 0; i < t.length; i++) {
                t[i] += v[i];
            }
        }
        return new UdpCounters(t[0], t[1], t[2], t[3], t[4], t[5], t[6], t[7], t[8], t[9], t[10]);
    }

    /** Stops the world's thread, then every cell, and closes their sockets. */
    @Override
    public void close() {
        running = false;
        Thread t = worldThread;
        if (t != null) {
            t.interrupt();
            try {
                t.join(TimeUnit.SECONDS.toMillis(5));
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
        List<CellHost> open;
        synchronized (hosts) {
            open = List.copyOf(hosts.values());
            hosts.clear();
        }
        open.forEach(CellHost::close);
    }

    /** Milliseconds of mission time since {@link #start}, {@code rate} of them per wall millisecond. */
    private static final class MissionClock implements Clock {
        private final double rate;
        private volatile long startNanos = -1;

        MissionClock(double rate) {
            this.rate = rate;
        }

        void start() {
            startNanos = System.nanoTime();
        }

        @Override
        public long nowMillis() {
            long s = startNanos;
            return s < 0 ? 0 : (long) ((System.nanoTime() - s) / 1e6 * rate);
        }
    }

    /** Drops what the world's radio would not carry to this vehicle now, and extra loss. */
    private static final class RadioFilter extends ForwardingTransport {
        private final Address self;
        private final WorldRadio radio;
        private final double loss;
        private final Random random;

        RadioFilter(Transport inner, Address self, WorldRadio radio, double loss, long seed) {
            super(inner);
            this.self = self;
            this.radio = radio;
            this.loss = loss;
            this.random = new Random(seed);
        }

        @Override
        public void setReceiver(Receiver receiver) {
            inner.setReceiver((from, data) -> {
                if (radio.reachable(from, self) && (loss == 0 || random.nextDouble() >= loss)) {
                    receiver.onDatagram(from, data);
                }
            });
        }
    }

    private static int freePort() throws IOException {
        try (DatagramSocket probe = new DatagramSocket(new InetSocketAddress("0.0.0.0", 0))) {
            return probe.getLocalPort();
        }
    }
}
