package net.smc.sim.team;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Collection;
import java.util.Deque;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.BiConsumer;
import java.util.function.BooleanSupplier;
import java.util.function.Consumer;
import java.util.function.Function;

import net.smc.core.cell.Cell;
import net.smc.core.cell.CellBuilder;
import net.smc.core.cell.CellEvent;
import net.smc.core.cell.Scheme;
import net.smc.core.capability.CapabilityDescription;
import net.smc.core.message.SharedDecodes;
import net.smc.core.mission.Mission;
import net.smc.core.role.TaskProvider;
import net.smc.core.security.IdealAuthentication;
import net.smc.core.security.SecureEndpoint;
import net.smc.core.security.SecureTransport;
import net.smc.core.security.TrustAnchor;
import net.smc.core.transport.Address;
import net.smc.core.transport.Transport;
import net.smc.core.transport.sim.InMemoryNetwork;
import net.smc.core.transport.sim.LinkProfile;
import net.smc.core.transport.sim.SimulationScheduler;
import net.smc.policy.api.PolicyRepository;
import net.smc.policy.lang.ParsedUnits;
import net.smc.sim.task.TaskCatalog;
import net.smc.sim.world.SimWorld;

/**
 * A whole team of cells on the in-memory network and one virtual clock: the deterministic
 * simulation the team protocols are tested on. One seed fixes everything (the network's loss and
 * delays, each cell's random choices), so a run replays exactly.
 *
 * <p>Time moves in steps ({@link #STEP_MILLIS}); after every step the {@link TeamInvariants} are
 * checked (unless {@link TeamSimulationBuilder#invariantChecks} turned that off), and a violation throws {@link InvariantViolation} with the seed and the end of the
 * trace. Faults are applied between steps: crashes and restarts, partitions and heals, link
 * profiles (loss, duplication, re-ordering, delay), joins and leaves.
 *
 * <p>A simulation may have a world ({@link TeamSimulationBuilder#world}): each vehicle placed at a start of the
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
public final class TeamSimulation implements CellTeam {
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
    /** Each vehicle by the address it is attached at. */
    private final Map<Address, String> byAddress = new java.util.HashMap<>();
    /** The last {@link #TRACE_LINES} events, made into lines only when the trace is read. */
    private final Deque<CellEvent> trace = new ArrayDeque<>();
    private final Consumer<CellEvent> listener;
    private final Function<String, TaskProvider> tasks;
    private final net.smc.policy.api.AuthMode auth;
    private final TeamInvariants invariants;
    private final boolean checking;
    private final List<Set<String>> partition = new ArrayList<>();
    private final Adversary adversary;
    private final WorldTeam world;
    /**
     * The parse of the boot file and of each role's files, shared by the team's cells (each still
     * runs them): a team of 1,000 would otherwise parse the same texts thousands of times.
     */
    private final ParsedUnits parsedUnits = new ParsedUnits(1_024, 16_384);
    /** Every cell receives each discovery broadcast: one decode serves them all. */
    private final SharedDecodes sharedDecodes = new SharedDecodes();
    private final BiConsumer<String, String> output;
    private int nextPort = 5000;
    /** {@link #cells()} as it stands, made again after a cell is booted or crashed (null: to make). */
    private List<Cell> liveCells;
    /** {@link #rogues()} as it stands, made again after a vehicle is added (null: to make). */
    private List<SimVehicle> rogues;
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

    TeamSimulation(TeamSimulationBuilder b) {
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
        this.trust = SimIdentities.trust(mission.instanceName());
        this.ideal = new IdealAuthentication(trust, sim);
        this.invariants = new TeamInvariants(this, b.mergeBoundMillis, b.verifyingReadings);
        this.checking = b.checking;
        this.output = b.output;
        this.world = b.arena == null ? null : new WorldTeam(this, SimWorld.builder(b.arena, sim).seed(seed).radio(b.radio).robotSpec(b.robotSpec).build(),
                b.catalog, b.places, b.standalone);
        if (world != null) {
            network.setRadio(world.world().radio());
        }
        for (SimVehicle v : b.vehicles) {
            add(v);
        }
        this.adversary = b.adversary ? new Adversary(network, sim, seed,
                nodes.values().stream().map(n -> n.address).toList()) : null;
        if (world != null) {
            world.checkPlaces(nodes.keySet(), b.arriving);
        }
    }

    public static TeamSimulationBuilder builder(Mission mission, PolicyRepository repository, long seed) {
        return new TeamSimulationBuilder(mission, repository, seed);
    }

    /**
     * Starts every vehicle's cell, and the adversary if there is one: the commanders last, so that
     * every other vehicle is listening when a commander starts and its first discovery reaches them.
     */
    @Override
    public void start() {
        if (adversary != null) {
            adversary.start();
        }
        if (world != null) {
            world.start();
        }
        for (boolean commanders : new boolean[] {false, true}) {
            for (Node n : nodes.values()) {
                if (n.cell == null && n.spec.commander() == commanders) {
                    boot(n, commanders);
                }
            }
        }
    }

    /** Adds a vehicle and starts it now. */
    public void join(SimVehicle vehicle) {
        Node n = add(vehicle);
        if (adversary != null) {
            adversary.target(n.address);
        }
        boot(n, vehicle.commander());
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
        byAddress.put(n.address, v.id());
        rogues = null;
        if (world != null) {
            world.bind(v.id(), n.address);
        }
        return n;
    }

    private void boot(Node n, boolean commander) {
        Transport raw = n.transport == null ? network.attach(n.address) : network.restart(n.address);
        Transport transport = switch (security) {
            case NONE -> raw;
            case IDEAL -> ideal.wrap(raw, SimIdentities.identity(n.spec, mission.instanceName()).credential());
            case REAL -> new SecureTransport(raw, SecureEndpoint.builder(SimIdentities.identity(n.spec, mission.instanceName()), trust, sim)
                    .random(SimIdentities.seeded(seed * 31 + n.address.port() + 7919L * restarts)).build());
        };
        n.transport = raw;
        TaskProvider provider = world != null && world.placed(n.spec.id()) ? world.tasks(n.spec.id()) : tasks.apply(n.spec.id());
        CapabilityDescription description = world != null && world.placed(n.spec.id())
                ? world.describe(n.spec) : n.spec.description();
        CellBuilder b = Cell.builder(n.spec.id(), mission, description)
                .transport(transport).clock(sim).scheduler(sim).repository(repository)
                .commander(commander).seed(seed * 1_000_003L + n.address.port() + 7919L * restarts)
                .trace(this::record).tasks(provider).parsedUnits(parsedUnits).sharedDecodes(sharedDecodes)
                .output(line -> output.accept(n.spec.id(), line)).auth(auth);
        if (scheme != null) {
            b.scheme(scheme);
        }
        n.cell = b.build();
        liveCells = null;
        if (checking) {
            Cell cell = n.cell;
            cell.onLinksChanged(() -> invariants.moved(cell));   // the checks re-read only the cells that changed
        }
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
        liveCells = null;
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
            check();
        }
    }

    private void check() {
        if (checking) {
            invariants.check();
        }
    }

    /**
     * Runs until {@code condition} holds (checked after every step), at most {@code maxMillis}.
     *
     * @return whether it came to hold
     */
    @Override
    public boolean runUntil(BooleanSupplier condition, long maxMillis) {
        long end = sim.nowMillis() + maxMillis;
        while (!condition.getAsBoolean()) {
            if (sim.nowMillis() >= end) {
                return false;
            }
            sim.runUntil(Math.min(end, sim.nowMillis() + STEP_MILLIS));
            check();
        }
        return true;
    }

    @Override
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
    @Override
    public Cell cell(String vehicle) {
        return node(vehicle).cell;
    }

    /** Live cells of honest vehicles. */
    public List<Cell> cells() {
        if (liveCells == null) {
            liveCells = nodes.values().stream().filter(n -> n.cell != null && !n.spec.rogue()).map(n -> n.cell).toList();
        }
        return liveCells;
    }

    @Override
    public Collection<SimVehicle> vehicles() {
        return nodes.values().stream().map(n -> n.spec).toList();
    }

    /** The rogue vehicles among {@link #vehicles()}. */
    List<SimVehicle> rogues() {
        if (rogues == null) {
            rogues = nodes.values().stream().map(n -> n.spec).filter(SimVehicle::rogue).toList();
        }
        return rogues;
    }

    @Override
    public SimVehicle vehicle(String id) {
        return node(id).spec;
    }

    @Override
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
    @Override
    public WorldTeam world() {
        return world;
    }

    /** The scheduler of the virtual clock (the world steps on it too). */
    @Override
    public SimulationScheduler scheduler() {
        return sim;
    }

    /** Where {@code vehicle} is attached to the network. */
    @Override
    public Address address(String vehicle) {
        return node(vehicle).address;
    }

    /**
     * The vehicle attached at {@code address}, if any: who sent a datagram the network carries (most
     * message headers leave their sender to the transport).
     */
    public java.util.Optional<String> vehicleAt(Address address) {
        return java.util.Optional.ofNullable(byAddress.get(address));
    }

    public InMemoryNetwork network() {
        return network;
    }

    /** The adversary on the channel, if the simulation has one. */
    public java.util.Optional<Adversary> adversary() {
        return java.util.Optional.ofNullable(adversary);
    }

    /** The ideal authentication of {@link Security#IDEAL} runs, with what it refused. */
    public IdealAuthentication idealAuthentication() {
        return ideal;
    }

    public TeamInvariants invariants() {
        return invariants;
    }

    /** The end of the trace, oldest first. */
    public List<String> trace() {
        return trace.stream().map(CellEvent::toString).toList();
    }

    /** Records a line in the trace (the harness's own fault actions use it too) and passes the event on. */
    public void record(CellEvent e) {
        listener.accept(e);
        if (trace.size() == TRACE_LINES) {
            trace.removeFirst();
        }
        trace.addLast(e);
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
}
