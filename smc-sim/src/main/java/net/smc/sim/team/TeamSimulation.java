package net.smc.sim.team;

import java.security.NoSuchAlgorithmException;
import java.security.SecureRandom;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Collection;
import java.util.Deque;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.BiConsumer;
import java.util.function.BooleanSupplier;
import java.util.function.Consumer;
import java.util.function.Function;

import net.smc.core.cell.Cell;
import net.smc.core.cell.CellEvent;
import net.smc.core.cell.Scheme;
import net.smc.core.capability.CapabilityDescription;
import net.smc.core.mission.Mission;
import net.smc.core.role.TaskProvider;
import net.smc.core.security.Claims;
import net.smc.core.security.Credential;
import net.smc.core.security.IdealAuthentication;
import net.smc.core.security.SigningIdentity;
import net.smc.core.security.SecureEndpoint;
import net.smc.core.security.SecureTransport;
import net.smc.core.security.SigningKey;
import net.smc.core.security.TrustAnchor;
import net.smc.core.transport.Address;
import net.smc.core.transport.Transport;
import net.smc.core.transport.sim.InMemoryNetwork;
import net.smc.core.transport.sim.LinkProfile;
import net.smc.core.transport.sim.SimulationScheduler;
import net.smc.policy.api.PolicyRepository;
import net.smc.sim.task.TaskCatalog;
import net.smc.sim.world.Arena;
import net.smc.sim.world.SimWorld;

/**
 * A whole team of cells on the in-memory network and one virtual clock: the deterministic
 * simulation the team protocols are tested on. One seed fixes everything (the network's loss and
 * delays, each cell's random choices), so a run replays exactly.
 *
 * <p>Time moves in steps ({@link #STEP_MILLIS}); after every step the {@link TeamInvariants} are
 * checked, and a violation throws {@link InvariantViolation} with the seed and the end of the
 * trace. Faults are applied between steps: crashes and restarts, partitions and heals, link
 * profiles (loss, duplication, re-ordering, delay), joins and leaves.
 *
 * <p>A simulation may have a world ({@link Builder#world}): each vehicle placed at a start of the
 * arena gets a robot there, each placed at a station is a cell without one; their tasks come
 * from a {@link TaskCatalog} on that hardware, their capability descriptions from those tasks,
 * and the world's radio carries their traffic ({@link WorldTeam}).
 *
 * <pre>{@code
 * TeamSimulation sim = TeamSimulation.builder(mission, repository, seed)
 *         .vehicles(SimVehicle.reconnaissance(2, 1, 2, 2)).build();
 * sim.start();
 * sim.runUntil(() -> sim.commanderState().equals(Optional.of(MissionState.OPTIMAL)), 60_000);
 * }</pre>
 */
public final class TeamSimulation {
    /** Virtual time between invariant checks. */
    public static final long STEP_MILLIS = 50;
    /** Trace lines kept for a failure report. */
    private static final int TRACE_LINES = 400;

    /** How cells prove who they are. */
    public enum Security {
        /** Credentials checked once, senders vouched for by the network ({@link IdealAuthentication}). */
        IDEAL,
        /** Signed and MAC'd datagrams ({@link SecureTransport}): slow (Ed25519), for a few seeds. */
        REAL,
        /** None: envelopes' senders are believed (no rogue may be simulated). */
        NONE
    }

    private static final Map<String, SigningIdentity> IDENTITIES = new ConcurrentHashMap<>();
    private static final SigningKey AUTHORITY = key(1);
    private static final SigningKey FOREIGN_AUTHORITY = key(2);

    private final Mission mission;
    private final PolicyRepository repository;
    private final long seed;
    private final Security security;
    private final Scheme scheme;
    private final SimulationScheduler sim = new SimulationScheduler();
    private final InMemoryNetwork network;
    private final IdealAuthentication ideal;
    private final TrustAnchor trust;
    private final Map<String, Node> nodes = new LinkedHashMap<>();
    private final Deque<String> trace = new ArrayDeque<>();
    private final Consumer<CellEvent> listener;
    private final Function<String, TaskProvider> tasks;
    private final net.smc.policy.api.AuthMode auth;
    private final TeamInvariants invariants;
    private final List<Set<String>> partition = new ArrayList<>();
    private final WorldTeam world;
    private final BiConsumer<String, String> output;
    private int nextPort = 5000;
    private long restarts;

    /** One vehicle: its spec, address, and its current cell (null while crashed). */
    static final class Node {
        final SimVehicle spec;
        final Address address;
        Cell cell;
        Transport transport;

        Node(SimVehicle spec, Address address) {
            this.spec = spec;
            this.address = address;
        }
    }

    private TeamSimulation(Builder b) {
        this.tasks = b.tasks;
        this.auth = b.auth;
        this.mission = b.mission;
        this.repository = b.repository;
        this.seed = b.seed;
        this.security = b.security;
        this.scheme = b.scheme;
        this.network = new InMemoryNetwork(sim, seed);
        this.network.setDefaultLink(b.link);
        this.listener = b.listener;
        this.trust = trust(mission.instanceName());
        this.ideal = new IdealAuthentication(trust, sim);
        this.invariants = new TeamInvariants(this, b.mergeBoundMillis);
        this.output = b.output;
        this.world = b.arena == null ? null : new WorldTeam(this, SimWorld.builder(b.arena, sim).seed(seed).build(),
                b.catalog, b.places, b.standalone);
        if (world != null) {
            network.setRadio(world.world().radio());
        }
        for (SimVehicle v : b.vehicles) {
            add(v);
        }
        if (world != null) {
            world.checkPlaces(nodes.keySet());
        }
    }

    public static Builder builder(Mission mission, PolicyRepository repository, long seed) {
        return new Builder(mission, repository, seed);
    }

    /** Starts every vehicle's cell. */
    public void start() {
        if (world != null) {
            world.start();
        }
        for (Node n : nodes.values()) {
            if (n.cell == null) {
                boot(n, n.spec.commander());
            }
        }
    }

    /** Adds a vehicle and starts it now. */
    public void join(SimVehicle vehicle) {
        boot(add(vehicle), vehicle.commander());
    }

    private Node add(SimVehicle v) {
        if (nodes.containsKey(v.id())) {
            throw new IllegalArgumentException("vehicle '" + v.id() + "' is already in the simulation");
        }
        if (v.rogue() && security == Security.NONE) {
            throw new IllegalArgumentException("a rogue vehicle needs authentication to be kept out; security is NONE");
        }
        Node n = new Node(v, Address.loopback(nextPort++));
        nodes.put(v.id(), n);
        if (world != null) {
            world.bind(v.id(), n.address);
        }
        return n;
    }

    private void boot(Node n, boolean commander) {
        Transport raw = n.transport == null ? network.attach(n.address) : network.restart(n.address);
        Transport transport = switch (security) {
            case NONE -> raw;
            case IDEAL -> ideal.wrap(raw, identity(n.spec, mission.instanceName()).credential());
            case REAL -> new SecureTransport(raw, SecureEndpoint.builder(identity(n.spec, mission.instanceName()), trust, sim)
                    .random(seeded(seed * 31 + n.address.port() + 7919L * restarts)).build());
        };
        n.transport = raw;
        TaskProvider provider = world != null && world.placed(n.spec.id()) ? world.tasks(n.spec.id()) : tasks.apply(n.spec.id());
        CapabilityDescription description = world != null && world.placed(n.spec.id())
                ? world.describe(n.spec) : n.spec.description();
        Cell.Builder b = Cell.builder(n.spec.id(), mission, description)
                .transport(transport).clock(sim).scheduler(sim).repository(repository)
                .commander(commander).seed(seed * 1_000_003L + n.address.port() + 7919L * restarts)
                .trace(this::record).tasks(provider)
                .output(line -> output.accept(n.spec.id(), line)).auth(auth);
        if (scheme != null) {
            b.scheme(scheme);
        }
        n.cell = b.build();
        if (world != null) {
            world.install(n.spec.id(), n.cell);
        }
        n.cell.start();
        if (world != null) {
            world.booted(n.spec.id(), n.cell, provider);
        }
    }


    /** Crashes a vehicle: its cell stops and its endpoint goes silent. */
    public void crash(String vehicle) {
        Node n = node(vehicle);
        if (n.cell == null) {
            return;
        }
        n.cell.stop();
        network.crash(n.address);
        n.cell = null;
        record(new CellEvent(sim.nowMillis(), vehicle, CellEvent.Kind.LEFT, "*** crashed"));
    }

    /** Restarts a crashed vehicle with a fresh cell (never as commander: that role went to a backup or is lost). */
    public void restart(String vehicle) {
        Node n = node(vehicle);
        if (n.cell != null) {
            return;
        }
        restarts++;
        record(new CellEvent(sim.nowMillis(), vehicle, CellEvent.Kind.LEFT, "*** restarted"));
        boot(n, false);
    }

    /** Leaves gracefully. */
    public void leave(String vehicle) {
        Cell c = node(vehicle).cell;
        if (c != null) {
            c.leave();
        }
    }

    public void rejoin(String vehicle) {
        Cell c = node(vehicle).cell;
        if (c != null) {
            c.rejoin();
        }
    }

    /** Cuts the network in two: {@code side} and everyone else. */
    public void partition(Collection<String> side) {
        heal();
        Set<String> a = new HashSet<>(side);
        Set<String> b = new HashSet<>(nodes.keySet());
        b.removeAll(a);
        partition.add(a);
        partition.add(b);
        network.partition(addresses(a), addresses(b));
        record(new CellEvent(sim.nowMillis(), "-", CellEvent.Kind.LEFT, "*** partition " + a + " | " + b));
    }

    public void heal() {
        if (!partition.isEmpty()) {
            record(new CellEvent(sim.nowMillis(), "-", CellEvent.Kind.LEFT, "*** heal"));
        }
        partition.clear();
        network.heal();
    }

    /** Sets every link's profile. */
    public void link(LinkProfile profile) {
        network.setDefaultLink(profile);
    }

    /** Runs for {@code millis} of virtual time, checking the invariants after every step. */
    public void run(long millis) {
        long end = sim.nowMillis() + millis;
        while (sim.nowMillis() < end) {
            sim.runUntil(Math.min(end, sim.nowMillis() + STEP_MILLIS));
            invariants.check();
        }
    }

    /**
     * Runs until {@code condition} holds (checked after every step), at most {@code maxMillis}.
     *
     * @return whether it came to hold
     */
    public boolean runUntil(BooleanSupplier condition, long maxMillis) {
        long end = sim.nowMillis() + maxMillis;
        while (!condition.getAsBoolean()) {
            if (sim.nowMillis() >= end) {
                return false;
            }
            sim.runUntil(Math.min(end, sim.nowMillis() + STEP_MILLIS));
            invariants.check();
        }
        return true;
    }

    public long nowMillis() {
        return sim.nowMillis();
    }

    public long seed() {
        return seed;
    }

    public Mission mission() {
        return mission;
    }

    /** The live cell of a vehicle, or null while it is crashed. */
    public Cell cell(String vehicle) {
        return node(vehicle).cell;
    }

    /** Live cells of honest vehicles. */
    public List<Cell> cells() {
        return nodes.values().stream().filter(n -> n.cell != null && !n.spec.rogue()).map(n -> n.cell).toList();
    }

    public Collection<SimVehicle> vehicles() {
        return nodes.values().stream().map(n -> n.spec).toList();
    }

    public SimVehicle vehicle(String id) {
        return node(id).spec;
    }

    public boolean isLive(String vehicle) {
        Node n = nodes.get(vehicle);
        return n != null && n.cell != null;
    }

    /** The groups of vehicles that can hear each other (one group when there is no partition). */
    public List<Set<String>> parts() {
        List<Set<String>> parts = partition.isEmpty() ? List.of(new HashSet<>(nodes.keySet())) : List.copyOf(partition);
        if (world == null) {
            return parts;
        }
        // In a world, a robot whose radio is off hears no one: it is a part of its own.
        Set<String> silent = world.silent();
        if (silent.isEmpty()) {
            return parts;
        }
        List<Set<String>> out = new ArrayList<>();
        for (Set<String> p : parts) {
            Set<String> rest = new HashSet<>(p);
            rest.removeAll(silent);
            out.add(rest);
        }
        silent.forEach(v -> out.add(Set.of(v)));
        return out;
    }

    /** The acting commanders among live honest cells. */
    public List<Cell> commanders() {
        return cells().stream().filter(Cell::isActingCommander).toList();
    }

    /** The world's side of the simulation, or null when it has no world. */
    public WorldTeam world() {
        return world;
    }

    /** The scheduler of the virtual clock (the world steps on it too). */
    public SimulationScheduler scheduler() {
        return sim;
    }

    /** Where {@code vehicle} is attached to the network. */
    public Address address(String vehicle) {
        return node(vehicle).address;
    }

    public InMemoryNetwork network() {
        return network;
    }

    public TeamInvariants invariants() {
        return invariants;
    }

    /** The end of the trace, oldest first. */
    public List<String> trace() {
        return List.copyOf(trace);
    }

    /** Records a line in the trace (the harness's own fault actions use it too) and passes the event on. */
    public void record(CellEvent e) {
        listener.accept(e);
        if (trace.size() == TRACE_LINES) {
            trace.removeFirst();
        }
        trace.addLast(e.toString());
    }

    private Node node(String vehicle) {
        Node n = nodes.get(vehicle);
        if (n == null) {
            throw new IllegalArgumentException("no vehicle '" + vehicle + "' in the simulation (vehicles: "
                    + nodes.keySet() + ")");
        }
        return n;
    }

    private Set<Address> addresses(Set<String> vehicles) {
        Set<Address> out = new HashSet<>();
        vehicles.forEach(v -> out.add(node(v).address));
        return out;
    }

    /**
     * The key and credential of a simulated or test vehicle for a mission, issued by the test
     * authority (a foreign one for a rogue). Made once per vehicle id and JVM: Ed25519 is slow and
     * they change no outcome.
     */
    public static SigningIdentity identity(SimVehicle v, String missionName) {
        return IDENTITIES.computeIfAbsent((v.rogue() ? "rogue:" : "") + v.id() + "@" + missionName, k -> {
            SigningKey key = key(k.hashCode() * 7919L + 3);
            SigningKey issuer = v.rogue() ? FOREIGN_AUTHORITY : AUTHORITY;
            return new SigningIdentity(key, Credential.issue(new Claims(v.id(), key.verificationKey(), missionName, 0,
                    Long.MAX_VALUE / 2), issuer));
        });
    }

    private static SigningKey key(long seed) {
        return SigningKey.generate(seeded(seed));
    }

    /** A SecureRandom that gives the same bytes for the same seed: for keys of simulated and test vehicles only. */
    public static SecureRandom seeded(long seed) {
        try {
            SecureRandom random = SecureRandom.getInstance("SHA1PRNG");
            random.setSeed(seed);
            return random;
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("SHA1PRNG is missing from this JDK", e);
        }
    }

    /** What the vehicles of {@link #identity} trust: the test authority, for that mission. */
    public static TrustAnchor trust(String missionName) {
        return new TrustAnchor(AUTHORITY.verificationKey(), missionName);
    }

    /** Collects a simulation's settings; vehicles are required. */
    public static final class Builder {
        private final Mission mission;
        private final PolicyRepository repository;
        private final long seed;
        private final List<SimVehicle> vehicles = new ArrayList<>();
        private Security security = Security.IDEAL;
        private Scheme scheme;
        private LinkProfile link = LinkProfile.DEFAULT.withLatency(5, 10);
        private long mergeBoundMillis = -1;
        private Consumer<CellEvent> listener = e -> { };
        private Function<String, TaskProvider> tasks = id -> TaskProvider.NONE;
        private BiConsumer<String, String> output = (vehicle, line) -> { };
        private Arena arena;
        private TaskCatalog catalog = TaskCatalog.standard();
        private final Map<String, String> places = new LinkedHashMap<>();
        private final Map<String, List<String>> standalone = new LinkedHashMap<>();
        private net.smc.policy.api.AuthMode auth = net.smc.policy.api.AuthMode.OFF;

        private Builder(Mission mission, PolicyRepository repository, long seed) {
            this.mission = Objects.requireNonNull(mission, "mission");
            this.repository = Objects.requireNonNull(repository, "repository");
            this.seed = seed;
        }

        public Builder vehicles(Collection<SimVehicle> team) {
            vehicles.addAll(team);
            return this;
        }

        public Builder security(Security security) {
            this.security = Objects.requireNonNull(security, "security");
            return this;
        }

        /** Overrides the mission's scheme. */
        public Builder scheme(Scheme scheme) {
            this.scheme = Objects.requireNonNull(scheme, "scheme");
            return this;
        }

        /** The initial profile of every link (5 ms latency, 10 ms jitter by default). */
        public Builder link(LinkProfile profile) {
            this.link = Objects.requireNonNull(profile, "profile");
            return this;
        }

        /** How long two acting commanders may hear each other before one must have stepped down. */
        public Builder mergeBound(long millis) {
            this.mergeBoundMillis = millis;
            return this;
        }

        /**
         * Receives every event of every cell, and the harness's own fault actions, as they happen
         * (the trace keeps only the last lines, as text): for measurements such as the time to a
         * mission state.
         */
        public Builder listener(Consumer<CellEvent> listener) {
            this.listener = Objects.requireNonNull(listener, "listener");
            return this;
        }

        /**
         * The tasks of each vehicle, by its id, asked each time its cell boots (so a restarted
         * vehicle may get fresh ones); default {@link TaskProvider#NONE} for every vehicle.
         */
        public Builder tasks(Function<String, TaskProvider> tasksOfVehicle) {
            this.tasks = Objects.requireNonNull(tasksOfVehicle, "tasksOfVehicle");
            return this;
        }

        /** Receives what each vehicle's policies print, with the vehicle's id. */
        public Builder output(BiConsumer<String, String> output) {
            this.output = Objects.requireNonNull(output, "output");
            return this;
        }

        /**
         * Puts the team in a world on this arena: the world steps on the simulation's clock, and
         * its radio carries the traffic of every vehicle ({@link #place} says where each is).
         */
        public Builder world(Arena arena) {
            this.arena = Objects.requireNonNull(arena, "arena");
            return this;
        }

        /** The tasks of placed vehicles, by name (default {@link TaskCatalog#standard()}). */
        public Builder catalog(TaskCatalog catalog) {
            this.catalog = Objects.requireNonNull(catalog, "catalog");
            return this;
        }

        /**
         * Places a vehicle in the world: at the arena's start {@code startOrStation} (it gets a
         * robot there) or at its station of that id (a cell without a robot). Every vehicle of a
         * simulation with a world must be placed.
         */
        public Builder place(String vehicle, String startOrStation) {
            Objects.requireNonNull(vehicle, "vehicle");
            Objects.requireNonNull(startOrStation, "startOrStation");
            if (places.containsKey(vehicle)) {
                throw new IllegalArgumentException("vehicle '" + vehicle + "' is placed already (at '" + places.get(vehicle) + "')");
            }
            places.put(vehicle, startOrStation);
            return this;
        }

        /**
         * Makes a placed vehicle stand outside the mission's roles: its tasks are started when its
         * cell boots and the repository files {@code policyUris} are loaded into it (the soldier's
         * wearable computer, say, whose policies drive its Beacon).
         */
        public Builder standalone(String vehicle, List<String> policyUris) {
            standalone.put(Objects.requireNonNull(vehicle, "vehicle"), List.copyOf(policyUris));
            return this;
        }

        /** The cells' authorisation mode (default OFF; DENY as deployed): see {@code Cell.Builder#auth}. */
        public Builder auth(net.smc.policy.api.AuthMode mode) {
            this.auth = Objects.requireNonNull(mode, "auth");
            return this;
        }

        public TeamSimulation build() {
            if (vehicles.isEmpty()) {
                throw new IllegalStateException("a simulation needs vehicles");
            }
            if (arena == null && (!places.isEmpty() || !standalone.isEmpty())) {
                throw new IllegalStateException("vehicles are placed, but the simulation has no world; call world(arena)");
            }
            return new TeamSimulation(this);
        }
    }
}
