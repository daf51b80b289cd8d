package net.smc.sim.team;

import java.util.ArrayList;
import java.util.Collection;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.function.BiConsumer;
import java.util.function.Consumer;
import java.util.function.Function;
import net.smc.core.cell.Cell;
import net.smc.core.cell.CellEvent;
import net.smc.core.cell.Scheme;
import net.smc.core.mission.Mission;
import net.smc.core.role.TaskProvider;
import net.smc.core.transport.sim.LinkProfile;
import net.smc.policy.api.PolicyRepository;
import net.smc.sim.task.TaskCatalog;
import net.smc.sim.arena.Arena;

/** Collects a simulation's settings; vehicles are required. */
public final class TeamSimulationBuilder {
    final Mission mission;
    final PolicyRepository repository;
    final long seed;
    final List<SimVehicle> vehicles = new ArrayList<>();
    TeamSimulation.Security security = TeamSimulation.Security.IDEAL;
    Scheme scheme;
    LinkProfile link = LinkProfile.DEFAULT.withLatency(5, 10);
    long mergeBoundMillis = -1;
    Consumer<CellEvent> listener = e -> { };
    Function<String, TaskProvider> tasks = id -> TaskProvider.NONE;
    BiConsumer<String, String> output = (vehicle, line) -> { };
    Arena arena;
    TaskCatalog catalog = TaskCatalog.standard();
    net.smc.sim.radio.RadioSettings radio = net.smc.sim.radio.RadioSettings.defaults();
    net.smc.sim.robot.KoalaSpec robotSpec = net.smc.sim.robot.KoalaSpec.koala();
    final Map<String, String> places = new LinkedHashMap<>();
    final Map<String, List<String>> standalone = new LinkedHashMap<>();
    final java.util.Set<String> arriving = new java.util.LinkedHashSet<>();
    net.smc.policy.api.AuthMode auth = net.smc.policy.api.AuthMode.OFF;
    boolean adversary;
    boolean checking = true;
    boolean verifyingReadings;

    TeamSimulationBuilder(Mission mission, PolicyRepository repository, long seed) {
        this.mission = Objects.requireNonNull(mission, "mission");
        this.repository = Objects.requireNonNull(repository, "repository");
        this.seed = seed;
    }

    public TeamSimulationBuilder vehicles(Collection<SimVehicle> team) {
        vehicles.addAll(team);
        return this;
    }

    public TeamSimulationBuilder security(TeamSimulation.Security security) {
        this.security = Objects.requireNonNull(security, "security");
        return this;
    }

    /** Overrides the mission's scheme. */
    public TeamSimulationBuilder scheme(Scheme scheme) {
        this.scheme = Objects.requireNonNull(scheme, "scheme");
        return this;
    }

    /** The initial profile of every link (5 ms latency, 10 ms jitter by default). */
    public TeamSimulationBuilder link(LinkProfile profile) {
        this.link = Objects.requireNonNull(profile, "profile");
        return this;
    }

    /** How long two acting commanders may hear each other before one must have stepped down. */
    public TeamSimulationBuilder mergeBound(long millis) {
        this.mergeBoundMillis = millis;
        return this;
    }

    /**
     * Receives every event of every cell, and the harness's own fault actions, as they happen
     * (the trace keeps only the last lines, as text): for measurements such as the time to a
     * mission state.
     */
    public TeamSimulationBuilder listener(Consumer<CellEvent> listener) {
        this.listener = Objects.requireNonNull(listener, "listener");
        return this;
    }

    /**
     * The tasks of each vehicle, by its id, asked each time its cell boots (so a restarted
     * vehicle may get fresh ones); default {@link TaskProvider#NONE} for every vehicle.
     */
    public TeamSimulationBuilder tasks(Function<String, TaskProvider> tasksOfVehicle) {
        this.tasks = Objects.requireNonNull(tasksOfVehicle, "tasksOfVehicle");
        return this;
    }

    /** Receives what each vehicle's policies print, with the vehicle's id. */
    public TeamSimulationBuilder output(BiConsumer<String, String> output) {
        this.output = Objects.requireNonNull(output, "output");
        return this;
    }

    /**
     * Puts the team in a world on this arena: the world steps on the simulation's clock, and
     * its radio carries the traffic of every vehicle ({@link #place} says where each is).
     */
    public TeamSimulationBuilder world(Arena arena) {
        this.arena = Objects.requireNonNull(arena, "arena");
        return this;
    }

    /** The world's radio (default {@link net.smc.sim.radio.RadioSettings#defaults()}). */
    public TeamSimulationBuilder radio(net.smc.sim.radio.RadioSettings settings) {
        this.radio = Objects.requireNonNull(settings, "radio");
        return this;
    }

    /** The build of every robot placed at a start (default {@link net.smc.sim.robot.KoalaSpec#koala()}). */
    public TeamSimulationBuilder robotSpec(net.smc.sim.robot.KoalaSpec spec) {
        this.robotSpec = Objects.requireNonNull(spec, "robotSpec");
        return this;
    }

    /** The tasks of placed vehicles, by name (default {@link TaskCatalog#standard()}). */
    public TeamSimulationBuilder catalog(TaskCatalog catalog) {
        this.catalog = Objects.requireNonNull(catalog, "catalog");
        return this;
    }

    /**
     * Places a vehicle in the world: at the arena's start {@code startOrStation} (it gets a
     * robot there) or at its station of that id (a cell without a robot). Every vehicle of a
     * simulation with a world must be placed.
     */
    public TeamSimulationBuilder place(String vehicle, String startOrStation) {
        Objects.requireNonNull(vehicle, "vehicle");
        Objects.requireNonNull(startOrStation, "startOrStation");
        if (places.containsKey(vehicle)) {
            throw new IllegalArgumentException("vehicle '" + vehicle + "' is placed already (at '" + places.get(vehicle) + "')");
        }
        places.put(vehicle, startOrStation);
        return this;
    }

    /**
     * Places a vehicle that is not among the simulation's vehicles yet: its robot stands at the
     * start {@code start}, switched off (no cell, no tasks), until {@link TeamSimulation#join}
     * adds the vehicle (robots entering one by one).
     */
    public TeamSimulationBuilder placeArriving(String vehicle, String start) {
        place(vehicle, start);
        arriving.add(vehicle);
        return this;
    }

    /**
     * Makes a placed vehicle stand outside the mission's roles: its tasks are started when its
     * cell boots and the repository files {@code policyUris} are loaded into it (the soldier's
     * wearable computer, say, whose policies drive its Beacon).
     */
    public TeamSimulationBuilder standalone(String vehicle, List<String> policyUris) {
        standalone.put(Objects.requireNonNull(vehicle, "vehicle"), List.copyOf(policyUris));
        return this;
    }

    /** The cells' authorisation mode (default OFF; DENY as deployed): see {@code CellBuilder#auth}. */
    public TeamSimulationBuilder auth(net.smc.policy.api.AuthMode mode) {
        this.auth = Objects.requireNonNull(mode, "auth");
        return this;
    }

    /**
     * Puts an {@link Adversary} on the channel: it replays, re-orders, bit-flips and forges
     * datagrams from the start to the end of the run. It needs authentication (IDEAL or REAL).
     */
    public TeamSimulationBuilder adversary(boolean on) {
        this.adversary = on;
        return this;
    }

    /**
     * Whether the invariants are checked after every step (default true). Off only to measure
     * what the cells themselves cost: a check every 50 ms of simulated time re-reads the cells that
     * told it their links changed (and those whose lease ran out), and walks the rules when anything did.
     */
    public TeamSimulationBuilder invariantChecks(boolean on) {
        this.checking = on;
        return this;
    }

    /**
     * With {@code on}, every invariant check also reads every cell in full and fails if the readings
     * it keeps from check to check (driven by the cells' link versions) are stale: for tests that
     * show no writer of a cell's links forgets to say so. Off by default (it costs a full read).
     */
    public TeamSimulationBuilder verifyInvariantReadings(boolean on) {
        this.verifyingReadings = on;
        return this;
    }

    public TeamSimulation build() {
        if (vehicles.isEmpty()) {
            throw new IllegalStateException("a simulation needs vehicles");
        }
        if (adversary && security == TeamSimulation.Security.NONE) {
            throw new IllegalStateException("an adversary needs authentication to be kept out; security is NONE");
        }
        if (arena == null && (!places.isEmpty() || !standalone.isEmpty())) {
            throw new IllegalStateException("vehicles are placed, but the simulation has no world; call world(arena)");
        }
        return new TeamSimulation(this);
    }
}
