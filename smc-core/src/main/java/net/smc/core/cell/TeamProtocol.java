package net.smc.core.cell;

import java.math.BigDecimal;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.Set;
import java.util.TreeMap;
import java.util.function.Consumer;

import net.smc.core.capability.CapabilityDescription;
import net.smc.core.capability.CapabilitySummary;
import net.smc.core.comm.CommunicationManager;
import net.smc.core.comm.DeliveryListener;
import net.smc.core.comm.FailureReason;
import net.smc.core.message.AssignmentResponse;
import net.smc.core.message.CapabilityReply;
import net.smc.core.message.CapabilityRequest;
import net.smc.core.message.Discovery;
import net.smc.core.message.DiscoveryReply;
import net.smc.core.message.Envelope;
import net.smc.core.message.Heartbeat;
import net.smc.core.message.Identity;
import net.smc.core.message.Invocation;
import net.smc.core.message.Leave;
import net.smc.core.message.Message;
import net.smc.core.message.MessageType;
import net.smc.core.message.PolicyRef;
import net.smc.core.message.PolicyReply;
import net.smc.core.message.PolicyRequest;
import net.smc.core.message.RoleAssignment;
import net.smc.core.message.RoleEvent;
import net.smc.core.message.Roster;
import net.smc.core.message.Status;
import net.smc.core.mission.Mission;
import net.smc.core.mission.MissionRole;
import net.smc.core.router.Subscriber;
import net.smc.core.transport.Address;
import net.smc.core.transport.Cancellable;
import net.smc.core.transport.Clock;
import net.smc.core.transport.Scheduler;

/**
 * The team protocols of one cell: management-tree formation and role assignment (the paper's
 * Algorithms 1 and 2), heartbeats and leases, failure detection and re-assignment, backup
 * commanders, merging of partitioned teams, graceful leave. Sans-IO: it acts only on messages the
 * Communication-Manager dispatches to it and on its own tick, on the cell's thread.
 *
 * <p>Policies decide, this class carries out: a discovery reply becomes a {@code newUAV} event and
 * the role-assignment policy (Table I) asks {@link #requestFullCapability}; a silent child becomes a
 * {@code UAVFailure} event and the re-assignment policy (Table II) asks {@link #reassign}. The rules
 * of seats, identities and priorities are {@link Slots}'; the times are {@link Timing}'s. See
 * <a href="doc-files/team-protocols.md">the team-protocols design note</a>.
 */
final class TeamProtocol implements Subscriber {
    /** Heartbeats between unchanged subtree reports. */
    private static final int REPORT_TICKS = 4;
    private static final String SIZE = "#size";
    private static final String HOSTED = "#hosted";

    /** What the protocol needs of the rest of its cell. */
    interface Host {
        /** Raises an event into the cell's policy engine. */
        void raise(String event, Object... values);

        /** Loads a role (all or nothing); the message of the exception says why not. */
        void loadRole(String role, PolicyStore store) throws Exception;

        /** Withdraws a role if it is loaded. */
        void withdrawRole(String role);

        /** The credential a peer authenticated with, as the discovery check wants it. */
        Object credentialOf(String vehicle);
    }

    private final String self;
    private final String missionId;
    private final Slots slots;
    private final Timing timing;
    /** {@link Timing#pendingMillis()}, derived once: it is read for every reservation every tick. */
    private final long pendingMillis;
    private final CommunicationManager comm;
    private final Clock clock;
    private final Scheduler scheduler;
    private final CapabilityDescription description;
    private final PolicyStore store;
    private final net.smc.policy.api.PolicyRepository repository;
    private final Host host;
    private final Consumer<CellEvent> trace;
    private final long tickPhaseMillis;

    // Where this cell stands.
    private boolean acting;
    private long epoch;
    private String commander;
    private Parent parent;
    /** The lease from the parent runs until then: the send time of the latest echoed heartbeat + the lease. */
    private long leaseUntilMillis;
    /** Whether the SUSPENDED event for the current lapse was emitted. */
    private boolean lapseNoted;
    /** Send times of recent heartbeats, by envelope id, to date the parent's echoes. */
    private final Map<Long, Long> heartbeatSentAt = new LinkedHashMap<>(32, 0.75f, false) {
        @Override
        protected boolean removeEldestEntry(Map.Entry<Long, Long> eldest) {
            return size() > 64;
        }
    };
    private boolean left;
    private final List<Seat> seats = new ArrayList<>();
    private Identity identity;
    private Incoming incoming;
    /** This cell's ancestors as its parent last told them: the parent first, the commander last. */
    private List<String> ancestors = List.of();
    private List<Object> handedOver = List.of();
    private List<Object> reportedState = List.of();
    private int teamSize;

    // As a manager.
    private final Map<Seat, Owned> owned = new TreeMap<>();
    private final Map<String, Child> children = new TreeMap<>();
    private final Map<String, PendingCapability> capabilityRequests = new HashMap<>();
    private final Map<String, Heard> heard = new HashMap<>();
    private final Map<String, List<Object>> handover = new HashMap<>();
    /**
     * Former children and assignees that may still name this cell as their parent (a Leave can be
     * lost), until their lease would have run out: taking a role from one of them could close a
     * cycle in the parent relation.
     */
    private final Map<String, Long> abandoned = new HashMap<>();
    private MissionState missionState;
    /** Whether the last tick found an open seat (a DISCOVERING event marks each start). */
    private boolean discovering;

    // As a backup commander.
    private Roster roster;
    private int backupRank = -1;
    private boolean prefetched;

    // Timers and counts.
    private Cancellable tickTimer;
    private long ticks;
    private boolean stopped;
    private List<Object> lastReport = List.of();
    private final Map<String, Long> rejected = new TreeMap<>();

    private record Parent(String vehicle, Address address) {
    }

    private record Incoming(String from, Address address, long envelopeId, RoleAssignment assignment, long sinceMillis) {
    }

    private record Heard(CapabilitySummary summary, long atMillis) {
    }

    private static final class PendingCapability {
        final Set<String> roles = new LinkedHashSet<>();
        final long sinceMillis;

        PendingCapability(long sinceMillis) {
            this.sinceMillis = sinceMillis;
        }
    }

    /** One seat this cell owns: who holds it, or who is being given it. */
    private static final class Owned {
        String holder;
        String pendingFor;
        long pendingSince;
    }

    private static final class Child {
        final String vehicle;
        Address address;
        long lastHeard;
        List<Seat> seats = List.of();
        CapabilityDescription description;
        List<Object> state = List.of();
        Map<String, Integer> subtree;
        int size = 1;
        int hosted;
        /** Envelope id of the latest heartbeat heard from it, echoed in every status. */
        long lastHeartbeat;
        /**
         * Whether its last report agreed with this cell's table. Its lease is renewed (its heartbeats
         * echoed) only then, so a child that claims a seat given to another stops counting until it
         * has given that seat back.
         */
        boolean consistent = true;
        /** Envelope id of the child's message that confirmed each seat (its ids only grow). */
        final Map<Seat, Long> confirmedBy = new HashMap<>();

        Child(String vehicle) {
            this.vehicle = vehicle;
        }
    }

    TeamProtocol(String self, Slots slots, Timing timing, CommunicationManager comm, Clock clock, Scheduler scheduler,
                 CapabilityDescription description, PolicyStore store, net.smc.policy.api.PolicyRepository repository,
                 Host host, Consumer<CellEvent> trace, long tickPhaseMillis) {
        this.self = self;
        this.slots = slots;
        this.missionId = slots.mission().instanceName();
        this.timing = timing;
        this.pendingMillis = timing.pendingMillis();
        this.comm = comm;
        this.clock = clock;
        this.scheduler = scheduler;
        this.description = description;
        this.store = store;
        this.repository = repository;
        this.host = host;
        this.trace = trace;
        this.tickPhaseMillis = tickPhaseMillis;
    }

    /** The message types this protocol handles. */
    static List<MessageType> handledTypes() {
        return List.of(MessageType.DISCOVERY, MessageType.DISCOVERY_REPLY, MessageType.CAPABILITY_REQUEST,
                MessageType.CAPABILITY_REPLY, MessageType.ROLE_ASSIGNMENT, MessageType.ASSIGNMENT_RESPONSE,
                MessageType.POLICY_REQUEST, MessageType.POLICY_REPLY, MessageType.HEARTBEAT, MessageType.STATUS,
                MessageType.ROLE_EVENT, MessageType.LEAVE, MessageType.ROSTER, MessageType.INVOCATION);
    }

    // ---------------------------------------------------------------- life cycle

    /** Starts ticking; as the acting commander when {@code commanding}. */
    void start(boolean commanding) {
        if (commanding) {
            Seat seat = Slots.commanderSeat();
            try {
                host.loadRole(Mission.COMMANDER, store);
            } catch (Exception e) {
                throw new IllegalStateException("'" + self + "' cannot act as commander: " + e.getMessage(), e);
            }
            acting = true;
            epoch = 0;
            commander = self;
            seats.add(seat);
            identity = identityOf(seat);
            recomputeOwnership();
            emit(CellEvent.Kind.COMMANDING, "acting commander of " + missionId + " " + identity + ", scheme "
                    + slots.scheme().name().toLowerCase());
        }
        tickTimer = scheduler.schedule(tickPhaseMillis, this::tick);
    }

    void stop() {
        stopped = true;
        if (tickTimer != null) {
            tickTimer.cancel();
        }
    }

    /** Leaves the team gracefully: tells parent and children, gives up every role, answers no discovery. */
    void leave() {
        left = true;
        if (parent != null) {
            send(parent.address(), new Leave("leaving the team"));
        }
        emit(CellEvent.Kind.LEFT, "leaves the team");
        dropEverything("left the team");
        if (acting) {
            acting = false;
        }
    }

    /** Ready to be discovered again after {@link #leave}. */
    void rejoin() {
        left = false;
    }

    private void tick() {
        if (stopped) {
            return;
        }
        ticks++;
        long now = clock.nowMillis();
        asChild(now);
        if (!owned.isEmpty() || acting) {
            asManager(now);
        }
        expireRequests(now);
        tickTimer = scheduler.schedule(timing.comTimeoutMillis(), this::tick);
    }

    // ---------------------------------------------------------------- dispatch

    @Override
    public void receive(Envelope envelope) {
        if (stopped || envelope.sender().equals(self)) {
            return;
        }
        Message body = envelope.body();
        if (body instanceof Discovery d) {
            onDiscovery(envelope, d);
        } else if (body instanceof DiscoveryReply r) {
            onDiscoveryReply(envelope, r);
        } else if (body instanceof CapabilityRequest r) {
            onCapabilityRequest(envelope, r);
        } else if (body instanceof CapabilityReply r) {
            onCapabilityReply(envelope, r);
        } else if (body instanceof RoleAssignment a) {
            onRoleAssignment(envelope, a);
        } else if (body instanceof AssignmentResponse r) {
            onAssignmentResponse(envelope, r);
        } else if (body instanceof PolicyRequest r) {
            onPolicyRequest(envelope, r);
        } else if (body instanceof PolicyReply r) {
            onPolicyReply(envelope, r);
        } else if (body instanceof Heartbeat h) {
            onHeartbeat(envelope, h);
        } else if (body instanceof Status st) {
            onStatus(envelope, st);
        } else if (body instanceof RoleEvent e) {
            onRoleEvent(envelope, e);
        } else if (body instanceof Leave l) {
            onLeave(envelope, l);
        } else if (body instanceof Roster r) {
            onRoster(envelope, r);
        } else if (body instanceof Invocation i) {
            onInvocation(envelope, i);
        } else {
            reject(envelope, "no handler for " + body.type());
        }
    }

    // ---------------------------------------------------------------- Algorithm 1: discovery

    private void onDiscovery(Envelope env, Discovery d) {
        if (!d.mission().equals(missionId)) {
            return;
        }
        if (acting && d.role().equals(Mission.COMMANDER)) {
            meetCommander(env.sender(), d.epoch());
            return;
        }
        boolean promotable = parent != null && !parent.vehicle().equals(env.sender())
                && slots.managedRoles(d.role()).stream().anyMatch(r -> promotion(r, d.epoch()));
        if ((!free() || left) && !promotable) {
            return; // Algorithm 1, line 9: a vehicle with a parent ignores discovery (unless it could move up)
        }
        address(env.sender()).ifPresent(a -> send(a, new DiscoveryReply(env.id(), missionId, description.summary())));
    }

    /** Two acting commanders met: the one with the higher epoch, then the lower vehicle id, stays. */
    private void meetCommander(String other, long otherEpoch) {
        boolean otherWins = otherEpoch > epoch || (otherEpoch == epoch && other.compareTo(self) < 0);
        if (!otherWins) {
            return;
        }
        emit(CellEvent.Kind.STEPPED_DOWN, "meets commander " + other + " of epoch " + otherEpoch + " (own epoch "
                + epoch + ") and steps down");
        acting = false;
        dropEverything("commander " + self + " stepped down for " + other);
        commander = null;
        epoch = 0;
    }

    private void onDiscoveryReply(Envelope env, DiscoveryReply r) {
        if (owned.isEmpty() || !r.mission().equals(missionId)) {
            return;
        }
        if (!r.summary().vehicle().equals(env.sender())) {
            reject(env, "capability summary names vehicle '" + r.summary().vehicle() + "'");
            return;
        }
        heard.put(env.sender(), new Heard(r.summary(), clock.nowMillis()));
        if (children.containsKey(env.sender()) || !hasVacancy()) {
            return;
        }
        // Table I decides whom to ask: newUAV(name uav lowLevelCap credential).
        host.raise("newUAV", "newUAV", env.sender(), r.summary(), host.credentialOf(env.sender()));
    }

    /** Broadcasts a discovery naming this cell's primary role. */
    private void discover() {
        Seat primary = seats.get(0);
        comm.broadcast(new Discovery(missionId, primary.role(), slots.level(primary.role()), epoch));
    }

    // ---------------------------------------------------------------- Algorithm 2: role assignment

    /** Asked by a policy ({@code root/discovery fullCapReq: uav role: r}): request the full description. */
    void requestFullCapability(String uav, String role) {
        if (slots.mission().role(role).isEmpty()) {
            emit(CellEvent.Kind.REJECTED, "policy asked for unknown role '" + role + "' for " + uav);
            return;
        }
        if (owned.keySet().stream().noneMatch(s -> s.role().equals(role) && open(s))) {
            return; // nothing to give for that role now
        }
        PendingCapability pending = capabilityRequests.get(uav);
        if (pending != null) {
            pending.roles.add(role);
            return;
        }
        Optional<Address> to = address(uav);
        if (to.isEmpty()) {
            return;
        }
        pending = new PendingCapability(clock.nowMillis());
        pending.roles.add(role);
        capabilityRequests.put(uav, pending);
        comm.send(to.get(), new CapabilityRequest(role), failureOnly(() -> capabilityRequests.remove(uav)));
    }

    private void onCapabilityRequest(Envelope env, CapabilityRequest r) {
        boolean fromParent = parent != null && parent.vehicle().equals(env.sender());
        if (!fromParent && (!free() || left) && !promotion(r.role(), epoch)) {
            return;
        }
        address(env.sender()).ifPresent(a -> comm.send(a, new CapabilityReply(env.id(), description)));
    }

    private void onCapabilityReply(Envelope env, CapabilityReply r) {
        PendingCapability pending = capabilityRequests.remove(env.sender());
        if (pending == null) {
            return;
        }
        CapabilityDescription full = r.description();
        if (!full.vehicle().equals(env.sender())) {
            reject(env, "capability description names vehicle '" + full.vehicle() + "'");
            return;
        }
        Child known = children.get(env.sender());
        if (known != null && !known.seats.isEmpty()) {
            known.description = full; // a child (from a roster, say): now this cell knows what it can do
            return;
        }
        // Algorithm 2, line 3: the description must match the requirement of one of the roles.
        Optional<Seat> seat = owned.keySet().stream()
                .filter(s -> pending.roles.contains(s.role()) && open(s))
                .filter(s -> slots.role(s.role()).requirement().isMetBy(full))
                .min(this::preferVacant);
        if (seat.isEmpty()) {
            return;
        }
        if (owned.values().stream().anyMatch(o -> env.sender().equals(o.pendingFor))) {
            return; // already being given a seat
        }
        giveSeat(env.sender(), full, seat.get());
    }

    /** Vacant seats first, then seats a vehicle of another role hosts; by priority. */
    private int preferVacant(Seat a, Seat b) {
        int c = Boolean.compare(owned.get(a).holder != null, owned.get(b).holder != null);
        return c != 0 ? c : slots.compare(a, b);
    }

    /** Whether a seat could go to a newly found vehicle: vacant, or only hosted, and nobody is being given it. */
    private boolean open(Seat seat) {
        Owned o = owned.get(seat);
        return o != null && o.pendingFor == null && (o.holder == null || hosted(seat, o.holder));
    }

    private boolean hasVacancy() {
        return owned.keySet().stream().anyMatch(this::open);
    }

    /** Whether the holder of a secondary seat holds it beside its own primary role. */
    private boolean hosted(Seat seat, String holder) {
        if (!slots.role(seat.role()).isSecondary()) {
            return false;
        }
        List<Seat> held = holder.equals(self) ? seats : children.containsKey(holder) ? children.get(holder).seats : List.of();
        return held.stream().anyMatch(s -> !slots.role(s.role()).isSecondary());
    }

    /** Gives {@code seat} to {@code vehicle}, releasing it from a host first. */
    private void giveSeat(String vehicle, CapabilityDescription full, Seat seat) {
        Owned o = owned.get(seat);
        if (o.holder != null) {
            String hostVehicle = o.holder;
            o.pendingFor = vehicle;
            o.pendingSince = clock.nowMillis();
            release(hostVehicle, seat, () -> {
                o.pendingFor = null;
                if (o.holder == null) {
                    assign(vehicle, full, seat);
                }
            });
            return;
        }
        assign(vehicle, full, seat);
    }

    /** Takes a hosted secondary seat back from its host (this cell, or a child), then runs {@code then}. */
    private void release(String holder, Seat seat, Runnable then) {
        if (holder.equals(self)) {
            dropOwnSeat(seat, "makes way for a vehicle of its own");
            owned.get(seat).holder = null;
            then.run();
            return;
        }
        Child child = children.get(holder);
        if (child == null) {
            owned.get(seat).holder = null;
            then.run();
            return;
        }
        comm.send(child.address, new Invocation(seat.role(), "release", List.of(BigDecimal.valueOf(seat.slot()))),
                new DeliveryListener() {
                    @Override
                    public void delivered(long id) {
                        Child c = children.get(holder);
                        if (c != null) {
                            c.seats = c.seats.stream().filter(s -> !s.equals(seat)).toList();
                        }
                        Owned o = owned.get(seat);
                        if (o != null && holder.equals(o.holder)) {
                            o.holder = null;
                        }
                        then.run();
                    }

                    @Override
                    public void failed(long id, FailureReason reason) {
                        Owned o = owned.get(seat);
                        if (o != null) {
                            o.pendingFor = null;
                        }
                    }
                });
    }

    /** Sends the role assignment (Algorithm 1, lines 6 and 15, once accepted). */
    private void assign(String vehicle, CapabilityDescription full, Seat seat) {
        Optional<Address> to = address(vehicle);
        Owned o = owned.get(seat);
        if (to.isEmpty() || o == null) {
            return;
        }
        List<Object> state = handover.getOrDefault(seat.role(), List.of());
        Child child = children.computeIfAbsent(vehicle, Child::new);
        RoleAssignment assignment = new RoleAssignment(missionId, seat.role(), identityOf(seat), self,
                policyRefs(seat.role()), epoch, state, child.seats.stream().map(Seat::toString).toList(), ancestors);
        o.pendingFor = vehicle;
        o.pendingSince = clock.nowMillis();
        child.address = to.get();
        child.description = full;
        if (child.seats.isEmpty()) {
            child.lastHeard = clock.nowMillis();
        }
        emit(CellEvent.Kind.ASSIGNING, seat + " " + identityOf(seat) + " to " + vehicle
                + (state.isEmpty() ? "" : " with handed-over state " + state));
        // Not delivered is not proof of not received (the Acks may be lost): the reservation stays
        // until it expires, an answer comes, or the vehicle's heartbeat shows it took the seat.
        comm.send(to.get(), assignment, failureOnly(() -> emit(CellEvent.Kind.ASSIGNMENT_FAILED, seat + " to "
                + vehicle + ": not acknowledged; the seat stays reserved until an answer or "
                + pendingMillis + " ms")));
    }

    private void onAssignmentResponse(Envelope env, AssignmentResponse r) {
        String vehicle = env.sender();
        Optional<Seat> seat = owned.entrySet().stream()
                .filter(e -> vehicle.equals(e.getValue().pendingFor) && e.getKey().role().equals(r.role()))
                .map(Map.Entry::getKey).findFirst();
        if (seat.isEmpty()) {
            Child child = children.get(vehicle);
            boolean known = child != null && child.seats.stream().anyMatch(s -> s.role().equals(r.role()));
            if (r.accepted() && !known) {
                revoke(vehicle, r.role());
            }
            return; // known: its heartbeat already told us it took the seat
        }
        if (!r.accepted()) {
            assignmentFailed(vehicle, seat.get(), "refused: " + r.reason());
            return;
        }
        accepted(vehicle, seat.get());
        Child c = children.get(vehicle);
        if (c != null) {
            c.confirmedBy.put(seat.get(), env.id());
        }
    }

    /**
     * A vehicle took a seat this cell no longer reserves for it (the reservation expired): it must
     * give the role back, or it would hold a seat that may have gone to another.
     */
    private void revoke(String vehicle, String role) {
        Child child = children.get(vehicle);
        Optional<Address> to = address(vehicle);
        if (to.isEmpty()) {
            return;
        }
        emit(CellEvent.Kind.REJECTED, vehicle + " took " + role + " after its reservation expired; revoked");
        if (child != null && !child.seats.isEmpty()) {
            comm.send(to.get(), new Invocation(role, "release", List.of()));
        } else {
            send(to.get(), new Leave("'" + self + "' no longer holds a seat of '" + role + "' for '" + vehicle + "'"));
        }
    }

    /** The vehicle took the seat: it is now a child holding it. */
    private void accepted(String vehicle, Seat seatTaken) {
        Optional<Seat> seat = Optional.of(seatTaken);
        Owned o = owned.get(seat.get());
        o.pendingFor = null;
        o.holder = vehicle;
        Child child = children.computeIfAbsent(vehicle, Child::new);
        child.address = address(vehicle).orElse(child.address);
        child.lastHeard = clock.nowMillis();
        List<Seat> before = child.seats;
        child.seats = slots.afterAssign(before, seat.get()).stream().filter(owned::containsKey).toList();
        for (Seat dropped : before) {
            if (!child.seats.contains(dropped) && owned.containsKey(dropped) && vehicle.equals(owned.get(dropped).holder)) {
                owned.get(dropped).holder = null;
            }
        }
        handover.remove(seat.get().role());
        heard.remove(vehicle);
        emit(CellEvent.Kind.ASSIGNED, seat.get() + " to " + vehicle + " (now holds " + child.seats + ")");
        sendRosterIfBackup();
        updateMissionState();
    }

    private void assignmentFailed(String vehicle, Seat seat, String why) {
        Owned o = owned.get(seat);
        if (o == null || !vehicle.equals(o.pendingFor)) {
            return;
        }
        o.pendingFor = null;
        Child child = children.get(vehicle);
        if (child != null && child.seats.isEmpty()) {
            children.remove(vehicle);
        }
        emit(CellEvent.Kind.ASSIGNMENT_FAILED, seat + " to " + vehicle + ": " + why);
    }

    // ---------------------------------------------------------------- the assignee

    private void onRoleAssignment(Envelope env, RoleAssignment a) {
        String from = env.sender();
        Optional<Address> back = address(from);
        if (back.isEmpty()) {
            return;
        }
        String refusal = refusal(from, a);
        if (refusal != null) {
            emit(CellEvent.Kind.REFUSED, a.role() + " from " + from + ": " + refusal);
            comm.send(back.get(), new AssignmentResponse(env.id(), a.role(), false, refusal));
            return;
        }
        if (incoming != null && incoming.envelopeId() == env.id() && incoming.from().equals(from)) {
            return;
        }
        incoming = new Incoming(from, back.get(), env.id(), a, clock.nowMillis());
        Set<String> listed = new LinkedHashSet<>();
        for (PolicyRef ref : a.policies()) {
            listed.add(ref.uri());
            if (!store.has(ref)) {
                comm.send(back.get(), new PolicyRequest(ref.uri(), ref.version()));
            }
        }
        // Whatever the role and the roles below it need that the assignment did not name.
        for (String uri : subtreePolicyUris(a.role())) {
            if (!listed.contains(uri) && store.get(uri, PolicyStore.ANY_VERSION).isEmpty()) {
                comm.send(back.get(), new PolicyRequest(uri, PolicyStore.ANY_VERSION));
            }
        }
        completeIfReady();
    }

    /** Why this cell will not take a role from {@code from}, or null when it will. */
    private String refusal(String from, RoleAssignment a) {
        if (!a.mission().equals(missionId)) {
            return "assignment is for mission '" + a.mission() + "', this vehicle serves '" + missionId + "'";
        }
        if (slots.mission().role(a.role()).isEmpty() || a.role().equals(Mission.COMMANDER)) {
            return "role '" + a.role() + "' cannot be assigned in mission '" + missionId + "'";
        }
        if (acting) {
            return "this vehicle is the acting commander";
        }
        if (left) {
            return "this vehicle has left the team";
        }
        if (a.ancestors().contains(self)) {
            return "'" + from + "' descends from this vehicle; taking a role from it would close a cycle";
        }
        Long until = abandoned.get(from);
        if (until != null && clock.nowMillis() < until) {
            return "'" + from + "' may still name this vehicle as its parent";
        }
        if (parent != null && !parent.vehicle().equals(from) && !promotion(a.role(), a.epoch())) {
            return "this vehicle already has parent '" + parent.vehicle() + "'";
        }
        if (incoming != null && !incoming.from().equals(from)) {
            return "this vehicle is taking a role from '" + incoming.from() + "'";
        }
        if (incoming != null && !incoming.assignment().role().equals(a.role())) {
            return "this vehicle is still taking role '" + incoming.assignment().role() + "'; one role at a time";
        }
        if (!slots.role(a.role()).requirement().isMetBy(description)) {
            return "this vehicle lacks " + slots.role(a.role()).requirement().missingFrom(description).describe();
        }
        return null;
    }

    private void completeIfReady() {
        Incoming in = incoming;
        if (in == null || !in.assignment().policies().stream().allMatch(store::has)
                || !policiesHeld(in.assignment().role())) {
            return;
        }
        incoming = null;
        RoleAssignment a = in.assignment();
        Seat seat = new Seat(a.role(), slotOf(a));
        if (parent != null && !parent.vehicle().equals(in.from())) {
            if (!promotion(a.role(), a.epoch())) {
                emit(CellEvent.Kind.REFUSED, seat + " from " + in.from() + ": no longer free to move up");
                comm.send(in.address(), new AssignmentResponse(in.envelopeId(), a.role(), false, "no longer free"));
                return;
            }
            emit(CellEvent.Kind.RELEASED, "moves up from " + seats + " under " + parent.vehicle() + " to " + seat
                    + " under " + in.from());
            send(parent.address(), new Leave("'" + self + "' moves up to " + seat + " under '" + in.from() + "'"));
            dropEverything("moves up to " + seat);
        }
        boolean sameParent = parent != null && parent.vehicle().equals(in.from());
        List<Seat> before = sameParent ? List.copyOf(seats) : List.of();
        // What the parent says this vehicle keeps from it, then its own (hosted) seats that still fit.
        List<Seat> kept = before.stream().filter(s -> a.keeps().contains(s.toString())).toList();
        List<Seat> after = new ArrayList<>(slots.afterAssign(kept, seat));
        for (Seat s : before) {
            if (!kept.contains(s) && ownsItself(before, s) && canAlsoHold(after, s)) {
                after.add(s);
            }
        }
        if (before.stream().noneMatch(s -> s.role().equals(seat.role()))) {
            try {
                host.loadRole(seat.role(), store);
            } catch (Exception e) {
                String why = "loading role '" + seat.role() + "' failed: " + e.getMessage();
                emit(CellEvent.Kind.REFUSED, seat + " from " + in.from() + ": " + why);
                comm.send(in.address(), new AssignmentResponse(in.envelopeId(), a.role(), false, truncate(why)));
                return;
            }
        }
        Set<String> keptRoles = new LinkedHashSet<>();
        after.forEach(s -> keptRoles.add(s.role()));
        for (Seat s : before) {
            if (!after.contains(s)) {
                if (!keptRoles.contains(s.role())) {
                    host.withdrawRole(s.role());
                }
                emit(CellEvent.Kind.RELEASED, s + ": gives way to " + seat);
            }
        }
        seats.clear();
        seats.addAll(after);
        parent = new Parent(in.from(), in.address());
        ancestors = lineage(in.from(), a.ancestors());
        epoch = a.epoch();
        lastStatusMillis = clock.nowMillis();
        // The answer leaves now; the parent hears it later, so its failure timeout starts later still.
        leaseUntilMillis = clock.nowMillis() + timing.leaseMillis();
        lapseNoted = false;
        if (!slots.role(seat.role()).isSecondary() || identity == null) {
            identity = a.identity();
        }
        recomputeOwnership();
        emit(CellEvent.Kind.ACCEPTED, seat + " " + a.identity() + " from " + in.from() + ", holds " + seats);
        comm.send(in.address(), new AssignmentResponse(in.envelopeId(), a.role(), true, ""));
        if (!a.handover().isEmpty()) {
            handedOver = a.handover();
            host.raise("handover", "handover", a.role(), a.handover());
        }
    }

    /**
     * Whether this vehicle, attached to its team, would move up to {@code role}: a role before its
     * own primary role in the mission's order (the surveyor before the detector), offered within its
     * own team, that it is able to hold. A team short of a surveyor then takes one from among its
     * detectors, as the reasonably-optimal configuration would.
     */
    private boolean promotion(String role, long offeredEpoch) {
        if (parent == null || suspended() || seats.isEmpty() || acting || offeredEpoch != epoch
                || slots.mission().role(role).isEmpty() || role.equals(Mission.COMMANDER)) {
            return false;
        }
        String mine = seats.get(0).role();
        return slots.rank(role) < slots.rank(mine) && slots.role(role).requirement().isMetBy(description);
    }

    /** The repository holder's fallback: a file of the local repository, if the cell has one. */
    private Optional<PolicyStore.Entry> fromRepository(String uri) {
        if (repository == null) {
            return Optional.empty();
        }
        try {
            return Optional.of(store.load(repository, uri));
        } catch (IllegalArgumentException missing) {
            return Optional.empty();
        }
    }

    /** The policy URIs of a role and of every role it manages, down the tree. */
    private List<String> subtreePolicyUris(String role) {
        Set<String> uris = new LinkedHashSet<>();
        List<String> pending = new ArrayList<>(List.of(role));
        while (!pending.isEmpty()) {
            MissionRole r = slots.role(pending.remove(0));
            uris.addAll(r.policies());
            uris.addAll(r.authorisations());
            pending.addAll(slots.managedRoles(r.name()));
        }
        return List.copyOf(uris);
    }

    /** A parent followed by its own ancestors, cut to the most a message carries. */
    private static List<String> lineage(String parentVehicle, List<String> above) {
        List<String> chain = new ArrayList<>();
        chain.add(parentVehicle);
        for (String a : above) {
            if (chain.size() == RoleAssignment.MAX_ANCESTORS) {
                break;
            }
            chain.add(a);
        }
        return List.copyOf(chain);
    }

    /** Whether {@code seat} is owned by another of {@code held}: a secondary seat this vehicle hosts itself. */
    private boolean ownsItself(List<Seat> held, Seat seat) {
        return slots.owner(seat).map(held::contains).orElse(false);
    }

    private int slotOf(RoleAssignment a) {
        for (int s = 0; s < slots.optimal(a.role()); s++) {
            if (slots.sequence(new Seat(a.role(), s)) == a.identity().sequence()) {
                return s;
            }
        }
        return 0;
    }

    private void onPolicyRequest(Envelope env, PolicyRequest r) {
        Optional<PolicyStore.Entry> entry = store.get(r.uri(), r.version());
        if (entry.isEmpty() && (acting || backupRank >= 0)) {
            entry = fromRepository(r.uri()).filter(e -> r.version() == PolicyStore.ANY_VERSION
                    || e.version() == r.version());
        }
        Optional<Address> back = address(env.sender());
        if (entry.isEmpty() || back.isEmpty()) {
            reject(env, "policy " + r.uri() + " version " + r.version() + " is not held here");
            return;
        }
        comm.send(back.get(), new PolicyReply(env.id(), r.uri(), entry.get().version(), entry.get().text()));
    }

    private void onPolicyReply(Envelope env, PolicyReply r) {
        if (!store.accept(r.uri(), r.version(), r.text())) {
            reject(env, "policy " + r.uri() + " arrived with version " + r.version() + " but its text has version "
                    + PolicyStore.versionOf(r.text()));
            return;
        }
        completeIfReady();
    }

    private void onInvocation(Envelope env, Invocation i) {
        if (!i.operation().equals("release") || parent == null || !parent.vehicle().equals(env.sender())) {
            reject(env, "invocation '" + i.operation() + "' on role '" + i.role() + "' is not accepted from "
                    + env.sender());
            return;
        }
        seats.stream().filter(s -> s.role().equals(i.role())).findFirst()
                .ifPresent(s -> dropOwnSeat(s, "released by its parent"));
    }

    // ---------------------------------------------------------------- heartbeats, leases, failures

    private long lastStatusMillis;
    private int reportCountdown;

    private void asChild(long now) {
        if (parent == null) {
            return;
        }
        if (seats.isEmpty()) {
            send(parent.address(), new Leave("'" + self + "' holds no role any more"));
            dropEverything("holds no role any more");
            return;
        }
        long silent = now - lastStatusMillis;
        if (backupRank >= 0 && commander != null && parent.vehicle().equals(commander)
                && silent > timing.takeoverMillis(backupRank)) {
            takeOver();
            return;
        }
        if (silent > timing.orphanMillis()) {
            emit(CellEvent.Kind.ORPHANED, "nothing from parent " + parent.vehicle() + " for " + silent + " ms; drops "
                    + seats);
            dropEverything("parent " + parent.vehicle() + " is lost");
            return;
        }
        if (suspended() && !lapseNoted) {
            lapseNoted = true;
            emit(CellEvent.Kind.SUSPENDED, "lease from " + parent.vehicle() + " ran out " + (now - leaseUntilMillis)
                    + " ms ago; last status " + silent + " ms ago");
        }
        // The heartbeat's state field carries the slot of the primary seat, so the parent knows the exact seat.
        long id = comm.send(parent.address(), new Heartbeat(seats.get(0).role(), epoch, seats.get(0).slot()));
        heartbeatSentAt.put(id, now);
        List<Object> report = reportValues();
        if (!report.equals(lastReport) || --reportCountdown <= 0) {
            reportCountdown = REPORT_TICKS;
            lastReport = report;
            send(parent.address(), new RoleEvent(seats.get(0).role(), "report", report));
        }
    }

    private void onHeartbeat(Envelope env, Heartbeat h) {
        Child child = children.get(env.sender());
        Optional<Address> back = address(env.sender());
        if (back.isEmpty()) {
            return;
        }
        // The heartbeat names the child's primary seat: it must be one this cell gave it.
        Seat primary = new Seat(h.role(), h.state());
        if (child == null || !child.seats.contains(primary)) {
            Optional<Seat> reserved = owned.containsKey(primary) && env.sender().equals(owned.get(primary).pendingFor)
                    ? Optional.of(primary) : Optional.empty();
            if (reserved.isEmpty()) {
                if (child != null) {
                    children.remove(env.sender());
                    vacate(child);
                    emit(CellEvent.Kind.REJECTED, env.sender() + " reports role " + h.role() + " but holds " + child.seats
                            + " from this cell; let go");
                }
                send(back.get(), new Leave("'" + env.sender() + "' is not a child of '" + self + "' as " + h.role()));
                return;
            }
            accepted(env.sender(), reserved.get()); // its answer was lost; its heartbeat says it took the seat
            child = children.get(env.sender());
            child.confirmedBy.put(reserved.get(), env.id());
        }
        child.lastHeard = clock.nowMillis();
        child.address = back.get();
        child.lastHeartbeat = Math.max(child.lastHeartbeat, env.id());
        sendStatus(child);
    }

    /** Tells a child the team's state, echoing its latest heartbeat heard (which renews its lease). */
    private void sendStatus(Child child) {
        if (child.address != null && identity != null) {
            send(child.address, new Status(missionId, identity, commander == null ? self : commander, epoch,
                    teamSize(), child.consistent ? child.lastHeartbeat : 0, ancestors));
        }
    }

    private void onStatus(Envelope env, Status s) {
        if (!s.mission().equals(missionId)) {
            return;
        }
        String from = env.sender();
        if (parent != null && parent.vehicle().equals(from)) {
            lastStatusMillis = clock.nowMillis();
            Long sentAt = heartbeatSentAt.get(s.echo());
            if (sentAt != null && sentAt + timing.leaseMillis() > leaseUntilMillis) {
                leaseUntilMillis = sentAt + timing.leaseMillis();
                lapseNoted = false;
            }
            epoch = s.epoch();
            commander = s.commander();
            teamSize = s.teamSize();
            ancestors = lineage(from, s.ancestors());
            return;
        }
        // A backup that took over claims the old commander's children.
        if (parent != null && parent.vehicle().equals(commander) && s.commander().equals(from) && s.epoch() > epoch) {
            emit(CellEvent.Kind.ADOPTED, "new commander " + from + " of epoch " + s.epoch() + " replaces " + commander);
            parent = new Parent(from, address(from).orElse(parent.address()));
            ancestors = List.of(from);
            commander = from;
            epoch = s.epoch();
            lastStatusMillis = clock.nowMillis();
            // Seats granted by the old commander count again only once the new one has echoed a heartbeat.
            leaseUntilMillis = clock.nowMillis() - 1;
            backupRank = -1;
            roster = null;
            reportCountdown = 0;
        }
    }

    private void onRoleEvent(Envelope env, RoleEvent e) {
        Child child = children.get(env.sender());
        if (child == null || !e.event().equals("report")) {
            return;
        }
        Map<String, Integer> counts = new LinkedHashMap<>();
        List<Object> state = List.of();
        List<Object> v = e.values();
        for (int i = 0; i + 1 < v.size(); i += 2) {
            if (v.get(i) instanceof String key && key.equals("#state") && v.get(i + 1) instanceof List<?> l) {
                state = List.copyOf(l);
            } else if (v.get(i) instanceof String key && key.equals("#seats") && v.get(i + 1) instanceof List<?> l) {
                reconcile(child, env.id(), l);
            } else if (v.get(i) instanceof String key && v.get(i + 1) instanceof BigDecimal n) {
                counts.put(key, n.intValue());
            }
        }
        child.size = counts.getOrDefault(SIZE, 1);
        child.hosted = counts.getOrDefault(HOSTED, 0);
        counts.remove(SIZE);
        counts.remove(HOSTED);
        child.subtree = counts;
        child.state = state;
        updateMissionState();
    }

    /**
     * Brings this cell's table in line with the seats a child says it holds (anti-entropy: answers,
     * Leaves and rosters can be lost). A claimed seat this cell gave to nobody is adopted; one it gave
     * to another is taken back from the child; a seat the table gives the child but the child no
     * longer claims is vacated, unless the report is older than the answer that confirmed it.
     */
    private void reconcile(Child child, long reportId, List<?> claimedNames) {
        Set<Seat> claimed = new LinkedHashSet<>();
        for (Object o : claimedNames) {
            if (o instanceof String name) {
                int hash = name.lastIndexOf('#');
                try {
                    claimed.add(new Seat(name.substring(0, hash), Integer.parseInt(name.substring(hash + 1))));
                } catch (RuntimeException bad) {
                    emit(CellEvent.Kind.REJECTED, child.vehicle + " reports seat '" + name + "'; seats are role#slot");
                }
            }
        }
        List<Seat> mine = new ArrayList<>(child.seats);
        boolean conflict = false;
        for (Seat s : claimed) {
            Owned o = owned.get(s);
            if (o == null || child.vehicle.equals(o.holder)) {
                continue;
            }
            if (child.vehicle.equals(o.pendingFor)) {
                accepted(child.vehicle, s);
                mine = new ArrayList<>(child.seats);
            } else if (o.holder == null && o.pendingFor == null) {
                o.holder = child.vehicle;
                mine.add(s);
                child.confirmedBy.put(s, reportId);
                emit(CellEvent.Kind.ASSIGNED, s + " adopted: " + child.vehicle + " reports holding it");
            } else {
                conflict = true;
                emit(CellEvent.Kind.REJECTED, child.vehicle + " reports " + s + ", which this cell gives "
                        + (o.holder != null ? o.holder : o.pendingFor) + "; taken back");
                address(child.vehicle).ifPresent(a -> comm.send(a, new Invocation(s.role(), "release", List.of())));
            }
        }
        for (Seat s : List.copyOf(mine)) {
            if (!claimed.contains(s) && reportId > child.confirmedBy.getOrDefault(s, Long.MIN_VALUE)) {
                mine.remove(s);
                Owned o = owned.get(s);
                if (o != null && child.vehicle.equals(o.holder)) {
                    o.holder = null;
                }
            }
        }
        child.seats = List.copyOf(mine);
        child.consistent = !conflict;
    }

    private void asManager(long now) {
        List<Child> silent = children.values().stream()
                .filter(c -> !c.seats.isEmpty() && now - c.lastHeard > timing.failureTimeoutMillis())
                // An assignment in flight may still make it keep its seats: wait for its answer or expiry.
                .filter(c -> owned.values().stream().noneMatch(o -> c.vehicle.equals(o.pendingFor))).toList();
        silent.forEach(c -> children.remove(c.vehicle));
        for (Child child : silent) {
            failed(child, now - child.lastHeard);
        }
        for (Child c : children.values()) {
            if (!c.seats.isEmpty()) {
                sendStatus(c);
                if (c.description == null && !capabilityRequests.containsKey(c.vehicle) && c.address != null) {
                    // A child known from a roster: learn what it can do, to move it if need be.
                    capabilityRequests.put(c.vehicle, new PendingCapability(now));
                    comm.send(c.address, new CapabilityRequest(c.seats.get(0).role()),
                            failureOnly(() -> capabilityRequests.remove(c.vehicle)));
                }
            }
        }
        fillSecondarySeats();
        swapTowardsOptimal(now);
        boolean open = hasVacancy();
        if (open && !discovering) {
            emit(CellEvent.Kind.DISCOVERING, "discovers for "
                    + owned.keySet().stream().filter(this::open).map(Seat::toString).toList());
        }
        discovering = open;
        if (open || (acting && ticks % Timing.BEACON_TICKS == 0)) {
            discover();
        }
        if (acting && ticks % Timing.ROSTER_TICKS == 0) {
            sendRoster();
        }
        updateMissionState();
    }

    /** A child was silent for the failure timeout: vacate its seats and raise UAVFailure for each. */
    private void failed(Child child, long silentMillis) {
        List<Seat> lost = child.seats;
        vacate(child);
        for (Seat s : lost) {
            handover.put(s.role(), child.state);
        }
        emit(CellEvent.Kind.FAILURE, child.vehicle + " silent for " + silentMillis + " ms; held " + lost
                + ", last state " + child.state);
        for (Seat s : lost) {
            // Table II decides: UAVFailure(name role uav state).
            host.raise("UAVFailure", "UAVFailure", s.role(), child.vehicle, child.state);
        }
        sendRosterIfBackup();
        updateMissionState();
    }

    /**
     * Asked by a policy ({@code root/role/<manager> reassign: role scheme: s}): find the role a new
     * holder. A free capable vehicle first; else a child moved from a role of lower priority; else
     * the team contracts (the seat stays vacant, a secondary one returns to its primary's vehicle).
     */
    void reassign(String managingRole, String role, String scheme) {
        Optional<Seat> seat = owned.keySet().stream().filter(s -> s.role().equals(role) && open(s)
                && owned.get(s).holder == null).min(slots::compare);
        if (seat.isEmpty()) {
            emit(CellEvent.Kind.REASSIGNING, role + " (scheme " + scheme + "): no vacant seat");
            return;
        }
        MissionRole wanted = slots.role(role);
        long now = clock.nowMillis();
        Optional<String> free = heard.entrySet().stream()
                .filter(e -> now - e.getValue().atMillis() <= timing.failureTimeoutMillis())
                .filter(e -> !children.containsKey(e.getKey()) && !capabilityRequests.containsKey(e.getKey()))
                .filter(e -> wanted.requirement().isMetBy(e.getValue().summary()))
                .map(Map.Entry::getKey).sorted().findFirst();
        if (free.isPresent()) {
            emit(CellEvent.Kind.REASSIGNING, seat.get() + " (scheme " + scheme + ") to free vehicle " + free.get());
            requestFullCapability(free.get(), role);
            return;
        }
        Optional<Child> movable = children.values().stream()
                .filter(c -> !c.seats.isEmpty() && c.description != null && wanted.requirement().isMetBy(c.description))
                .filter(c -> c.seats.stream().allMatch(s -> !s.role().equals(role) && slots.compare(s, seat.get()) > 0))
                .filter(c -> owned.values().stream().noneMatch(o -> c.vehicle.equals(o.pendingFor)))
                .max(Comparator.comparing((Child c) -> c.seats.get(0), slots::compare));
        if (movable.isPresent()) {
            Child c = movable.get();
            emit(CellEvent.Kind.REASSIGNING, seat.get() + " (scheme " + scheme + ") moves " + c.vehicle + " from "
                    + c.seats);
            assign(c.vehicle, c.description, seat.get());
            return;
        }
        emit(CellEvent.Kind.REASSIGNING, seat.get() + " (scheme " + scheme + "): no vehicle free; the team contracts");
        fillSecondarySeats();
    }

    /** Frees the seats this cell's table gives a child it no longer has. */
    private void vacate(Child child) {
        for (Seat s : child.seats) {
            Owned o = owned.get(s);
            if (o != null && child.vehicle.equals(o.holder)) {
                o.holder = null;
            }
        }
    }

    /** Vacant seats of secondary roles go to the vehicle holding their primary seat, if it may take them. */
    private void fillSecondarySeats() {
        for (Map.Entry<Seat, Owned> e : owned.entrySet()) {
            Seat seat = e.getKey();
            Owned o = e.getValue();
            if (o.holder != null || o.pendingFor != null) {
                continue;
            }
            Optional<Seat> hostSeat = slots.host(seat);
            if (hostSeat.isEmpty()) {
                continue;
            }
            if (seats.contains(hostSeat.get()) && !suspended()) {
                hostLocally(seat, o);
                continue;
            }
            // The seat's own host, else (when this cell owns the primary's seats too, as the
            // centralised commander does) any holder of the primary role that may take it.
            List<Seat> hosts = new ArrayList<>(List.of(hostSeat.get()));
            owned.keySet().stream().filter(h -> h.role().equals(hostSeat.get().role()) && !h.equals(hostSeat.get()))
                    .forEach(hosts::add);
            for (Seat h : hosts) {
                Owned ho = owned.get(h);
                Child c = ho == null || ho.holder == null ? null : children.get(ho.holder);
                if (c != null && c.description != null && canAlsoHold(c.seats, seat)
                        && owned.values().stream().noneMatch(x -> c.vehicle.equals(x.pendingFor))
                        && slots.role(seat.role()).requirement().isMetBy(c.description)) {
                    assign(c.vehicle, c.description, seat);
                    break;
                }
            }
        }
    }

    /**
     * A vacant seat no free vehicle can take goes to a child whose seats all come later in the
     * mission's order (a vehicle moved from a lower-priority role, as re-assignment does after a
     * failure): the surveyor's seat before the relay's.
     */
    private boolean promoteChild(Seat open) {
        MissionRole wanted = slots.role(open.role());
        Optional<Child> movable = children.values().stream()
                .filter(c -> !c.seats.isEmpty() && c.description != null && wanted.requirement().isMetBy(c.description))
                .filter(c -> c.seats.stream().allMatch(s -> slots.rank(s.role()) > slots.rank(open.role())))
                .filter(c -> owned.values().stream().noneMatch(o -> c.vehicle.equals(o.pendingFor)))
                .max(Comparator.comparing((Child c) -> c.seats.get(0), slots::compare));
        if (movable.isEmpty()) {
            return false;
        }
        emit(CellEvent.Kind.REASSIGNING, open + ": moves " + movable.get().vehicle + " up from " + movable.get().seats);
        assign(movable.get().vehicle, movable.get().description, open);
        return true;
    }

    /**
     * A local improvement towards the reasonably-optimal configuration: an open seat (vacant, or
     * hosted) that no free vehicle heard of can take goes to a child holding a seat of another role
     * that a free vehicle can take; that seat is then refilled through discovery. So a surveyor-like
     * vehicle detecting hazards becomes the relay, and the free detector the detector.
     */
    private void swapTowardsOptimal(long now) {
        for (Seat open : owned.keySet().stream().filter(this::open).sorted(slots::compare).toList()) {
            MissionRole wanted = slots.role(open.role());
            List<CapabilitySummary> free = heard.entrySet().stream()
                    .filter(e -> now - e.getValue().atMillis() <= timing.failureTimeoutMillis())
                    .filter(e -> !children.containsKey(e.getKey()) && !capabilityRequests.containsKey(e.getKey()))
                    .map(e -> e.getValue().summary()).toList();
            if (free.stream().anyMatch(f -> wanted.requirement().isMetBy(f))) {
                continue; // discovery will fill it directly
            }
            if (owned.get(open).holder == null && promoteChild(open)) {
                return;
            }
            if (free.isEmpty()) {
                continue; // nobody to swap with
            }
            for (Child c : children.values()) {
                if (c.seats.size() != 1 || c.description == null || !wanted.requirement().isMetBy(c.description)
                        || owned.values().stream().anyMatch(x -> c.vehicle.equals(x.pendingFor))) {
                    continue;
                }
                Seat held = c.seats.get(0);
                if (held.role().equals(open.role()) || canAlsoHold(List.of(held), open)
                        || slots.compare(held, open) < 0 && !slots.minimal(open)) {
                    continue;
                }
                MissionRole current = slots.role(held.role());
                if (free.stream().anyMatch(f -> current.requirement().isMetBy(f))) {
                    emit(CellEvent.Kind.REASSIGNING, open + ": moves " + c.vehicle + " from " + held
                            + ", which a free vehicle can take");
                    giveSeat(c.vehicle, c.description, open);
                    return;
                }
            }
        }
    }

    private boolean canAlsoHold(List<Seat> held, Seat seat) {
        if (held.stream().anyMatch(s -> s.role().equals(seat.role()))) {
            return false;
        }
        List<String> names = new ArrayList<>();
        held.forEach(s -> names.add(s.role()));
        names.add(seat.role());
        return slots.mission().allowsOnOneVehicle(names);
    }

    private void hostLocally(Seat seat, Owned o) {
        if (!canAlsoHold(seats, seat) || !slots.role(seat.role()).requirement().isMetBy(description)) {
            return;
        }
        if (!policiesHeld(seat.role())) {
            requestMissingPolicies(seat.role());
            return;
        }
        try {
            host.loadRole(seat.role(), store);
        } catch (Exception ex) {
            emit(CellEvent.Kind.REJECTED, "cannot host " + seat + ": " + ex.getMessage());
            return;
        }
        seats.add(seat);
        o.holder = self;
        recomputeOwnership();
        emit(CellEvent.Kind.HOSTING, seat + " beside " + seats.get(0));
        updateMissionState();
    }

    /** Asks the parent (or, for a repository holder, the local repository) for a role's missing files. */
    private void requestMissingPolicies(String role) {
        for (String uri : subtreePolicyUris(role)) {
            if (store.get(uri, PolicyStore.ANY_VERSION).isPresent()) {
                continue;
            }
            if ((acting || backupRank >= 0) && fromRepository(uri).isPresent()) {
                continue;
            }
            if (parent != null) {
                send(parent.address(), new PolicyRequest(uri, PolicyStore.ANY_VERSION));
            }
        }
    }

    private boolean policiesHeld(String role) {
        MissionRole r = slots.role(role);
        return r.policies().stream().allMatch(u -> store.get(u, PolicyStore.ANY_VERSION).isPresent())
                && r.authorisations().stream().allMatch(u -> store.get(u, PolicyStore.ANY_VERSION).isPresent());
    }

    private void onLeave(Envelope env, Leave l) {
        String from = env.sender();
        if (parent != null && parent.vehicle().equals(from)) {
            emit(CellEvent.Kind.LEFT, "parent " + from + " says: " + l.reason());
            dropEverything("parent " + from + " let go: " + l.reason());
            return;
        }
        Child child = children.remove(from);
        if (child != null) {
            vacate(child);
            emit(CellEvent.Kind.LEFT, "child " + from + " left (" + l.reason() + "); vacated " + child.seats);
            updateMissionState();
        }
    }

    // ---------------------------------------------------------------- backup commanders

    private void sendRosterIfBackup() {
        if (acting) {
            sendRoster();
        }
    }

    /** Replicates the team roster to the backups: the first children able to command, by identity. */
    private void sendRoster() {
        if (!acting || timing.backups() == 0) {
            return;
        }
        MissionRole cdr = slots.role(Mission.COMMANDER);
        List<Child> able = children.values().stream()
                .filter(c -> !c.seats.isEmpty() && c.description != null && cdr.requirement().isMetBy(c.description))
                .sorted(Comparator.comparing((Child c) -> slots.sequence(c.seats.get(0))))
                .limit(timing.backups()).toList();
        if (able.isEmpty()) {
            return;
        }
        List<Roster.Entry> members = new ArrayList<>();
        for (Child c : children.values()) {
            for (Seat s : c.seats) {
                if (members.size() < Roster.MAX_MEMBERS && c.address != null) {
                    members.add(new Roster.Entry(c.vehicle, c.address.toString(), s.role(), s.slot()));
                }
            }
        }
        Roster r = new Roster(missionId, epoch, able.stream().map(c -> c.vehicle).toList(), members);
        for (Child b : able) {
            send(b.address, r);
        }
    }

    private void onRoster(Envelope env, Roster r) {
        if (parent == null || !parent.vehicle().equals(env.sender()) || !env.sender().equals(commander)
                || !r.mission().equals(missionId)) {
            return;
        }
        roster = r;
        backupRank = r.backups().indexOf(self);
        if (backupRank >= 0 && !prefetched) {
            prefetched = true;
            for (String uri : allPolicyUris()) {
                if (store.get(uri, PolicyStore.ANY_VERSION).isEmpty()) {
                    send(parent.address(), new PolicyRequest(uri, PolicyStore.ANY_VERSION));
                }
            }
        }
    }

    /** The commander went silent: this backup leads the team in the next epoch. */
    private void takeOver() {
        for (String uri : allPolicyUris()) {
            if (store.get(uri, PolicyStore.ANY_VERSION).isEmpty()) {
                fromRepository(uri);
            }
        }
        if (!policiesHeld(Mission.COMMANDER)) {
            emit(CellEvent.Kind.REJECTED, "cannot take over: the commander's policies are not all here");
            backupRank = -1;
            return;
        }
        Roster r = roster;
        String old = commander;
        try {
            host.loadRole(Mission.COMMANDER, store);
        } catch (Exception e) {
            emit(CellEvent.Kind.REJECTED, "cannot take over: " + e.getMessage());
            backupRank = -1;
            return;
        }
        Set<String> formerChildren = new LinkedHashSet<>(children.keySet());
        for (Seat s : List.copyOf(seats)) {
            dropOwnSeat(s, "takes over as commander");
        }
        seats.clear();
        seats.add(Slots.commanderSeat());
        identity = identityOf(Slots.commanderSeat());
        acting = true;
        parent = null;
        ancestors = List.of();
        commander = self;
        epoch = r.epoch() + 1;
        backupRank = -1;
        roster = null;
        children.clear();
        owned.clear();
        recomputeOwnership();
        long now = clock.nowMillis();
        for (Roster.Entry e : r.members()) {
            if (e.vehicle().equals(self) || e.vehicle().equals(old) || formerChildren.contains(e.vehicle())) {
                continue; // this cell's own children were just let go; the roster's word on them is stale
            }
            Seat seat = new Seat(e.role(), e.slot());
            Owned o = owned.get(seat);
            if (o == null) {
                continue;
            }
            Address address;
            try {
                address = Address.parse(e.address());
            } catch (IllegalArgumentException bad) {
                continue;
            }
            comm.learnAddress(e.vehicle(), address);
            Child c = children.computeIfAbsent(e.vehicle(), Child::new);
            c.address = address;
            c.lastHeard = now;
            c.consistent = false; // the roster may be stale: trust its seats once its own report agrees
            List<Seat> held = new ArrayList<>(c.seats);
            held.add(seat);
            c.seats = List.copyOf(held);
            o.holder = e.vehicle();
        }
        emit(CellEvent.Kind.TOOK_OVER, "commander " + old + " silent; leads epoch " + epoch + " with children "
                + children.keySet());

        for (Child c : children.values()) {
            send(c.address, new Status(missionId, identity, self, epoch, teamSize()));
        }
        discover();
        updateMissionState();
    }

    // ---------------------------------------------------------------- seats and ownership

    /** Gives up one of this cell's seats (and the role, unless another seat needs it). */
    private void dropOwnSeat(Seat seat, String why) {
        if (!seats.remove(seat)) {
            return;
        }
        host.withdrawRole(seat.role());
        Owned mine = owned.get(seat);
        if (mine != null && self.equals(mine.holder)) {
            mine.holder = null;
        }
        emit(CellEvent.Kind.RELEASED, seat + ": " + why);
        recomputeOwnership();
    }

    /** Gives up every seat and child; becomes a free vehicle. */
    private void dropEverything(String why) {
        long until = clock.nowMillis() + timing.orphanMillis();
        for (Child c : children.values()) {
            if (c.address != null && !c.seats.isEmpty()) {
                send(c.address, new Leave(why));
            }
            abandoned.put(c.vehicle, until);
        }
        owned.values().stream().filter(o -> o.pendingFor != null).forEach(o -> abandoned.put(o.pendingFor, until));
        children.clear();
        owned.clear();
        capabilityRequests.clear();
        for (Seat s : List.copyOf(seats)) {
            host.withdrawRole(s.role());
            emit(CellEvent.Kind.RELEASED, s + ": " + why);
        }
        seats.clear();
        parent = null;
        ancestors = List.of();
        identity = null;
        backupRank = -1;
        roster = null;
        incoming = null;
        missionState = null;
        if (!acting) {
            commander = null;
        }
    }

    /** Re-derives the seats this cell owns from the seats it holds, keeping what it knew of them. */
    private void recomputeOwnership() {
        Set<Seat> now = new LinkedHashSet<>();
        for (Seat s : seats) {
            now.addAll(slots.ownedBy(s));
        }
        owned.keySet().retainAll(now);
        for (Seat s : now) {
            owned.computeIfAbsent(s, k -> new Owned());
        }
        for (Map.Entry<Seat, Owned> e : owned.entrySet()) {
            boolean mine = seats.contains(e.getKey());
            if (mine) {
                e.getValue().holder = self;
            } else if (self.equals(e.getValue().holder)) {
                e.getValue().holder = null;
            }
        }
        for (Child c : List.copyOf(children.values())) {
            List<Seat> kept = c.seats.stream().filter(owned::containsKey).toList();
            if (kept.size() != c.seats.size()) {
                c.seats = kept;
                if (kept.isEmpty()) {
                    children.remove(c.vehicle);
                    if (c.address != null) {
                        send(c.address, new Leave("'" + self + "' no longer manages its seats"));
                    }
                }
            }
        }
    }

    private Identity identityOf(Seat seat) {
        return new Identity(missionId, slots.level(seat.role()), slots.sequence(seat));
    }

    /** The policies of a role and of every role below it, as this cell holds them. */
    private List<PolicyRef> policyRefs(String role) {
        List<PolicyRef> refs = new ArrayList<>();
        for (String uri : subtreePolicyUris(role)) {
            store.ref(uri).ifPresent(refs::add);
        }
        return refs;
    }

    private List<String> allPolicyUris() {
        Set<String> uris = new LinkedHashSet<>();
        for (MissionRole r : slots.mission().roles()) {
            uris.addAll(r.policies());
            uris.addAll(r.authorisations());
        }
        return List.copyOf(uris);
    }

    // ---------------------------------------------------------------- counts and mission state

    /** Holders per role in this cell's subtree, itself included (suspended holders do not count). */
    Map<String, Integer> subtreeCounts() {
        Map<String, Integer> counts = slots.count(suspended() ? List.of() : seats);
        for (Child c : children.values()) {
            Map<String, Integer> sub = c.subtree != null ? c.subtree : slots.count(c.seats);
            sub.forEach((role, n) -> counts.merge(role, n, Integer::sum));
        }
        return counts;
    }

    private int hostedCount() {
        int n = suspended() ? 0 : (int) seats.stream().filter(s -> hosted(s, self)).count();
        for (Child c : children.values()) {
            n += c.hosted;
        }
        return n;
    }

    private int teamSize() {
        return acting ? subtreeSize() : teamSize;
    }

    private int subtreeSize() {
        int n = 1;
        for (Child c : children.values()) {
            n += c.size;
        }
        return n;
    }

    private List<Object> reportValues() {
        List<Object> v = new ArrayList<>();
        subtreeCounts().forEach((role, n) -> {
            if (n > 0) {
                v.add(role);
                v.add(BigDecimal.valueOf(n));
            }
        });
        v.add(SIZE);
        v.add(BigDecimal.valueOf(subtreeSize()));
        v.add(HOSTED);
        v.add(BigDecimal.valueOf(hostedCount()));
        v.add("#seats");
        v.add(seats.stream().map(Seat::toString).toList());
        if (!reportedState.isEmpty() && v.size() < 60) {
            v.add("#state");
            v.add(reportedState);
        }
        return v;
    }

    private void updateMissionState() {
        if (!acting) {
            return;
        }
        Map<String, Integer> counts = subtreeCounts();
        MissionState next = MissionState.OPTIMAL;
        for (String role : slots.roles()) {
            int n = counts.getOrDefault(role, 0);
            MissionRole r = slots.role(role);
            int min = role.equals(Mission.COMMANDER) ? 1 : r.minimal();
            if (n < min) {
                next = MissionState.FORMING;
                break;
            }
            if (n < slots.optimal(role)) {
                next = MissionState.RUNNING;
            }
        }
        if (next == MissionState.OPTIMAL && hostedCount() > 0) {
            next = MissionState.RUNNING;
        }
        if (next != missionState) {
            missionState = next;
            emit(CellEvent.Kind.MISSION_STATE, next + " " + counts + " hosted " + hostedCount());
            host.raise("missionState", "missionState", next.name().toLowerCase());
        }
    }

    // ---------------------------------------------------------------- state reported by tasks

    /** Sets the state this vehicle reports to its parent (its position, say), handed over if it fails. */
    void reportState(List<Object> state) {
        reportedState = List.copyOf(state);
    }

    List<Object> handedOver() {
        return handedOver;
    }

    // ---------------------------------------------------------------- views

    boolean acting() {
        return acting;
    }

    /** Whether the lease from the parent has run out: this cell's seats do not count until renewed. */
    boolean suspended() {
        return parent != null && !acting && clock.nowMillis() > leaseUntilMillis;
    }

    long epoch() {
        return epoch;
    }

    Optional<String> parent() {
        return parent == null ? Optional.empty() : Optional.of(parent.vehicle());
    }

    List<Seat> seats() {
        return List.copyOf(seats);
    }

    Optional<Identity> identity() {
        return Optional.ofNullable(identity);
    }

    Map<String, List<Seat>> children() {
        Map<String, List<Seat>> out = new TreeMap<>();
        children.forEach((v, c) -> {
            if (!c.seats.isEmpty()) {
                out.put(v, c.seats);
            }
        });
        return out;
    }

    Optional<String> commander() {
        return Optional.ofNullable(commander);
    }

    Optional<MissionState> missionState() {
        return Optional.ofNullable(missionState);
    }

    /** Messages refused, by reason. */
    Map<String, Long> rejected() {
        return rejected;
    }

    boolean left() {
        return left;
    }

    CellView view() {
        Map<String, List<String>> kids = new TreeMap<>();
        children().forEach((v, s) -> kids.put(v, s.stream().map(Seat::toString).toList()));
        return new CellView(self, missionId, identity == null ? null : identity.toString(), epoch, commander, acting,
                parent == null ? null : parent.vehicle(), suspended(), seats.stream().map(Seat::toString).toList(), kids,
                acting ? missionState : null, acting ? subtreeCounts() : Map.of(), clock.nowMillis());
    }

    // ---------------------------------------------------------------- helpers

    /** Free: no parent, no role, not commanding, not taking a role. */
    private boolean free() {
        return parent == null && !acting && seats.isEmpty() && incoming == null;
    }

    private void expireRequests(long now) {
        abandoned.values().removeIf(until -> now >= until);
        capabilityRequests.values().removeIf(p -> now - p.sinceMillis > timing.failureTimeoutMillis());
        heard.values().removeIf(h -> now - h.atMillis() > 4 * timing.failureTimeoutMillis());
        for (Map.Entry<Seat, Owned> e : owned.entrySet()) {
            Owned o = e.getValue();
            if (o.pendingFor != null && now - o.pendingSince > pendingMillis) {
                assignmentFailed(o.pendingFor, e.getKey(), "no answer within " + pendingMillis + " ms");
            }
        }
        if (incoming != null && now - incoming.sinceMillis() > timing.failureTimeoutMillis()) {
            Incoming in = incoming;
            incoming = null;
            emit(CellEvent.Kind.REFUSED, in.assignment().role() + " from " + in.from() + ": its policies did not arrive");
            send(in.address(), new AssignmentResponse(in.envelopeId(), in.assignment().role(), false,
                    "policies did not arrive in time"));
        }
    }

    private Optional<Address> address(String vehicle) {
        return comm.addressOf(vehicle);
    }

    private void send(Address to, Message m) {
        comm.send(to, m);
    }

    private void reject(Envelope env, String why) {
        rejected.merge(env.type().name(), 1L, Long::sum);
        emit(CellEvent.Kind.REJECTED, env.type() + " from " + env.sender() + ": " + why);
    }

    private void emit(CellEvent.Kind kind, String detail) {
        trace.accept(new CellEvent(clock.nowMillis(), self, kind, detail));
    }

    private static String truncate(String s) {
        return s.length() <= 255 ? s : s.substring(0, 252) + "...";
    }

    private static DeliveryListener failureOnly(Runnable onFailure) {
        Objects.requireNonNull(onFailure);
        return new DeliveryListener() {
            @Override
            public void failed(long id, FailureReason reason) {
                onFailure.run();
            }
        };
    }
}
