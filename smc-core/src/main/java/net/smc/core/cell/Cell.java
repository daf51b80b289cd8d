package net.smc.core.cell;

import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.SplittableRandom;
import java.util.function.Consumer;

import net.smc.core.capability.CapabilityDescription;
import net.smc.core.comm.CommunicationManager;
import net.smc.core.discovery.DiscoveryObject;
import net.smc.core.message.CellRequest;
import net.smc.core.message.Identity;
import net.smc.core.mission.Mission;
import net.smc.core.role.RoleLoadException;
import net.smc.core.role.Caller;
import net.smc.core.role.ExternalGateway;
import net.smc.policy.api.AuthMode;
import net.smc.core.role.Role;
import net.smc.core.role.RoleManager;
import net.smc.core.role.TaskProvider;
import net.smc.core.router.MessageRouter;
import net.smc.core.security.AuthenticatingTransport;
import net.smc.core.security.Credential;
import net.smc.core.transport.Clock;
import net.smc.core.transport.Scheduler;
import net.smc.core.transport.Transport;
import net.smc.policy.api.Diagnostic;
import net.smc.policy.api.TeamAddress;
import net.smc.core.transport.Address;
import net.smc.policy.api.TeamLink;
import net.smc.policy.RunResult;

/**
 * One vehicle's self-managed cell, wired: its policy engine, Role-Manager, capability description,
 * Communication-Manager and team protocols, on an injected {@link Clock}, {@link Scheduler} and
 * {@link Transport}. Start here to run a vehicle.
 *
 * <p>The engine holds what the paper's policies use: the event templates of
 * {@code policy:/boot/events}, {@code root/discovery} (Table I's {@code uav:has:cap:auth:} and
 * {@code fullCapReq:role:}), and, per role held, {@code root/role/<name>} with
 * {@code reassign:scheme:} (Table II). The protocols raise {@code newUAV}, {@code UAVFailure},
 * {@code handover} and {@code missionState} into it, and the policies decide.
 *
 * <pre>{@code
 * Cell cell = Cell.builder("uav1", mission, capabilities.description())
 *         .transport(transport).clock(sim).scheduler(sim).repository(repository)
 *         .commander(true).seed(1).trace(events::add).build();
 * cell.start();
 * }</pre>
 *
 * <p>Sans-IO and single-threaded: call it, and let its transport and scheduler call it, on one
 * thread. On an {@link AuthenticatingTransport} it believes only proven senders, and the discovery
 * check accepts a vehicle only with a credential for it; on a plain transport (tests, benchmarks)
 * it believes what envelopes claim.
 */
public final class Cell {
    /** Where the team object is: {@code root/team}. */
    public static final String TEAM = "team";
    private final String vehicle;
    private final Mission mission;
    private final Slots slots;
    private final net.smc.policy.PolicyEngine engine;
    private final RoleManager roles;
    private final CommunicationManager comm;
    private final TeamProtocol protocol;
    private final PolicyStore store = new PolicyStore();
    private final List<Diagnostic> diagnostics = new ArrayList<>();
    private final boolean commanding;
    private final TaskProvider tasks;
    private final ExternalGateway gateway;
    private final VehicleRoles vehicleRoles;
    private boolean started;

    Cell(CellBuilder b) {
        this.vehicle = b.vehicle;
        this.mission = b.mission;
        this.commanding = b.commander;
        this.tasks = b.tasks;
        Scheme scheme = b.scheme != null ? b.scheme
                : mission.parameter("scheme").map(p -> Scheme.parse(String.valueOf(p.value()))).orElse(Scheme.DISTRIBUTED);
        this.slots = new Slots(mission, scheme);
        Timing timing = b.timing != null ? b.timing : Timing.of(mission);
        SplittableRandom random = new SplittableRandom(b.seed);
        Consumer<String> output = b.output;
        this.engine = net.smc.policy.PolicyEngine.builder()
                .clock(b.clock::nowMillis)
                .scheduler((delay, task) -> b.scheduler.schedule(delay, task)::cancel)   // timers in the cell's (virtual) time
                .random(random.split())
                .repository(b.repository)
                .parsedUnits(b.parsedUnits)
                .output(output)
                .auth(b.auth)
                .errors(d -> {
                    diagnostics.add(d);
                    b.trace.accept(new CellEvent(b.clock.nowMillis(), vehicle, CellEvent.Kind.REJECTED,
                            "policy error: " + d));
                })
                .build();
        RunResult boot = engine.load("policy:/boot/events");
        if (!boot.diagnostics().isEmpty()) {
            throw new IllegalStateException("cell '" + vehicle + "' cannot boot: policy:/boot/events: " + boot.diagnostics());
        }
        engine.root().put(TEAM, net.smc.policy.PolicyEngine.manage(new TeamObject(this)));
        if (b.auth != AuthMode.OFF) {
            engine.endBoot();
        }
        MessageRouter router = new MessageRouter();
        this.comm = CommunicationManager.builder(vehicle, b.transport, b.clock, b.scheduler)
                .random(random.split()).router(router).sharedDecodes(b.sharedDecodes)
                .senderLeftToTransport(EnumSet.complementOf(EnumSet.copyOf(UnverifiedReads.READ_UNCHECKED)))
                .settings(b.senderSettings != null ? b.senderSettings : timing.senderSettings()).build();
        AuthenticatingTransport auth = b.transport instanceof AuthenticatingTransport a ? a : null;
        TeamProtocol.Host host = new TeamProtocol.Host() {
            @Override
            public void raise(String event, Object... values) {
                engine.raise("root/event/" + event, values);
            }

            @Override
            public void loadRole(String role, PolicyStore from) throws RoleLoadException {
                roles.load(vehicleRoles.roleOf(role, from));
            }

            @Override
            public void withdrawRole(String role) {
                if (roles.isLoaded(role)) {
                    roles.withdraw(role);
                }
            }

            @Override
            public Optional<Credential> credentialOf(String peer) {
                return auth == null ? Optional.empty() : auth.credentialOf(peer);
            }

            @Override
            public boolean checkHeld(Address from) {
                return auth != null && auth.checkHeld(from);
            }

            @Override
            public void deliver(Caller caller, String role, String event, List<Object> values) {
                gateway.raise(caller, role, event, values.toArray());
            }

            @Override
            public Object invoke(Caller caller, String role, String operation, List<Object> args) {
                return gateway.invoke(caller, role, operation, args.toArray());
            }

            @Override
            public void receiveEvent(Caller caller, String path, String selector, String event,
                                     Map<String, Object> attributes) {
                gateway.receiveEvent(caller, path, selector, event, attributes);
            }

            @Override
            public Object evaluate(Caller caller, String text, boolean printed) {
                return gateway.evaluate(caller, text, printed);
            }

            @Override
            public void report(String error) {
                engine.runtime().report(new Diagnostic(null, error));
            }

            @Override
            public long policyVersion() {
                return engine.policyVersion();
            }

            @Override
            public List<Object> taskStates() {
                return vehicleRoles.taskStates();
            }

            @Override
            public void importTaskStates(String role, List<Object> handedOver) {
                vehicleRoles.importTaskStates(role, handedOver);
            }
        };
        this.protocol = new TeamProtocol(TeamContext.builder().self(vehicle).slots(slots).timing(timing).comm(comm)
                .clock(b.clock).scheduler(b.scheduler).description(b.description).store(store)
                .repository(b.repository).host(host).trace(b.trace).build(), random.nextLong(timing.comTimeoutMillis()));
        this.roles = RoleManager.builder(engine).reassignment(protocol::reassign).build();
        this.vehicleRoles = new VehicleRoles(vehicle, slots, tasks, protocol::seats, roles::isLoaded, this::publish,
                diagnostics::add);
        this.gateway = new ExternalGateway(roles);
        new DiscoveryObject((uav, credential) -> accepts(auth, uav, credential), protocol).install(engine);
        protocol.register(router);
        if (auth != null) {
            protocol.shareDecodes(b.sharedDecodes);
            auth.setUnverifiedFilter(protocol::ignoresUnverified);
            auth.holdUnverified(protocol::readsUnverified, protocol::onUnverified);
        }
        engine.teamLink(new TeamLink() {
            @Override
            public long forwardEvent(TeamAddress to, String selector, String event, Map<String, Object> attributes) {
                return protocol.request(CellRequest.Kind.EVENT, to.cell(), to.path(), selector == null ? "" : selector, event,
                        WireValues.of(attributes));
            }

            @Override
            public long evaluate(String to, String text, boolean printed) {
                return protocol.request(CellRequest.Kind.EVALUATE, to, "", printed ? "test:" : "execute:", "", text);
            }
        });
        if (commanding) {
            if (b.repository == null) {
                throw new IllegalStateException("the acting commander '" + vehicle + "' needs the policy repository");
            }
            store.loadMission(b.repository, mission);
        }
    }

    /** A builder for vehicle {@code vehicle} of {@code mission}, describing itself as {@code description}. */
    public static CellBuilder builder(String vehicle, Mission mission, CapabilityDescription description) {
        return new CellBuilder(vehicle, mission, description);
    }

    /** Starts receiving and ticking; the acting commander starts forming its team. */
    public void start() {
        if (started) {
            throw new IllegalStateException("cell '" + vehicle + "' is already started");
        }
        started = true;
        comm.start();
        protocol.start(commanding);
    }

    /** Stops ticking and sending; the transport belongs to the caller. */
    public void stop() {
        protocol.stop();
        comm.stop();
    }

    /** Leaves the team gracefully (tells parent and children, gives up every role). */
    public void leave() {
        protocol.leave();
    }

    /** Answers discovery again after {@link #leave()}. */
    public void rejoin() {
        protocol.rejoin();
    }

    /**
     * Sets the state this vehicle reports to its parent with its heartbeats (its position, say):
     * if it fails, the parent hands this over to its replacement. Numbers, strings, booleans and
     * lists of them.
     */
    public void reportState(List<Object> state) {
        protocol.reportState(state);
    }

    /**
     * Publishes an event of {@code role} to the roles of other vehicles that subscribe to it (the
     * mission's {@code <interface>}); a task's event that a held role publishes is published by
     * itself. Values as messages carry them (strings, numbers, booleans, nil, lists).
     *
     * @return how many tree neighbours it was sent to
     */
    public int publish(String role, String event, List<Object> values) {
        return protocol.publish(role, event, WireValues.list(values));
    }

    /**
     * Invokes {@code operation} of {@code role} on the vehicle holding it, acting as {@code callerRole};
     * the answer is raised here as {@code root/event/remoteResult} with the returned call number.
     */
    public long invoke(String callerRole, String role, String operation, List<Object> args) {
        return protocol.invoke(callerRole, role, operation, WireValues.list(args));
    }

    /** The first role this cell holds whose mission interface publishes {@code event}. */
    Optional<String> publishingRole(String event) {
        return vehicleRoles.publishingRole(event);
    }

    /** The state handed over with the last role this vehicle took (empty if none). */
    public List<Object> handedOver() {
        return protocol.handedOver();
    }

    public String vehicle() {
        return vehicle;
    }

    public Mission mission() {
        return mission;
    }

    public Slots slots() {
        return slots;
    }

    public boolean isActingCommander() {
        return protocol.acting();
    }

    /** Whether this cell's lease from its parent ran out (its roles do not count until renewed). */
    public boolean isSuspended() {
        return protocol.suspended();
    }

    public long epoch() {
        return protocol.epoch();
    }

    public Optional<String> parent() {
        return protocol.parent();
    }

    public Optional<String> commander() {
        return protocol.commander();
    }

    /** The seats this vehicle holds, primary first. */
    public List<Seat> seats() {
        return protocol.seats();
    }

    /**
     * Whether this vehicle holds exactly {@code seats}, in that order: what {@code seats().equals(seats)}
     * says, without copying them (for checks that read a thousand cells often).
     */
    public boolean holdsSeats(List<Seat> seats) {
        return protocol.holdsSeats(seats);
    }

    /** The vehicle id of this cell's parent, or null when it has none: {@link #parent()} without an Optional. */
    public String parentOrNull() {
        return protocol.parentOrNull();
    }

    /**
     * A number that grows whenever this cell's parent, command, seats, children or their seats
     * change, or its lease is set other than by a renewal that only moves its end later: what a
     * check of many cells reads (or hears of: {@link #onLinksChanged}) to skip the unchanged ones.
     * Without it moving, {@link #isSuspended()}
     * may turn true once the clock passes {@link #leaseUntilMillis()}, and false again when the
     * lease is renewed; {@link #leaseUntilMillis()} may grow.
     */
    public long linkVersion() {
        return protocol.linkVersion();
    }

    /**
     * Runs {@code listener} (on the cell's thread) every time {@link #linkVersion()} moves, replacing
     * any listener set before (null: none): a check of many cells hears which ones changed without
     * visiting the others.
     */
    public void onLinksChanged(Runnable listener) {
        protocol.onLinksChanged(listener);
    }

    /** When the lease from the parent runs out: after it the cell is suspended (until renewed). */
    public long leaseUntilMillis() {
        return protocol.leaseUntilMillis();
    }

    public Optional<Identity> identity() {
        return protocol.identity();
    }

    /** Children by vehicle id, with the seats each holds from this cell. */
    public Map<String, List<Seat>> children() {
        return protocol.children();
    }

    /** Whether {@code vehicle} is among {@link #children()}, without building them. */
    public boolean hasChild(String vehicle) {
        return protocol.hasChild(vehicle);
    }

    /** For the acting commander, the mission's state. */
    public Optional<MissionState> missionState() {
        return protocol.missionState();
    }

    /** For the acting commander, holders per role in its team. */
    public Map<String, Integer> teamCounts() {
        return protocol.subtreeCounts();
    }

    public boolean hasLeft() {
        return protocol.left();
    }

    /** Messages the protocols refused, by message type. */
    public Map<String, Long> rejected() {
        return protocol.rejected();
    }

    /** Errors reported by policies since the cell started. */
    public List<Diagnostic> diagnostics() {
        return List.copyOf(diagnostics);
    }

    public CellView view() {
        return protocol.view();
    }

    /** The policy engine, for tasks and tests that reach into it. */
    public net.smc.policy.PolicyEngine engine() {
        return engine;
    }

    public RoleManager roleManager() {
        return roles;
    }

    public CommunicationManager communication() {
        return comm;
    }

    /** The discovery check: a credential issued to that vehicle for this mission (proven by the transport). */
    private boolean accepts(AuthenticatingTransport auth, String uav, Object credential) {
        if (auth == null) {
            return true;
        }
        return credential instanceof Credential c && c.vehicleId().equals(uav)
                && (c.mission() == null || c.mission().isEmpty() || c.mission().equals(mission.instanceName()));
    }
}
