package net.smc.core.cell;

import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.function.BiConsumer;

import net.smc.core.discovery.DiscoveryActions;
import net.smc.core.message.AssignmentResponse;
import net.smc.core.message.CapabilityReply;
import net.smc.core.message.CapabilityRequest;
import net.smc.core.message.Discovery;
import net.smc.core.message.DiscoveryReply;
import net.smc.core.message.Echo;
import net.smc.core.message.Envelope;
import net.smc.core.message.Heartbeat;
import net.smc.core.message.Identity;
import net.smc.core.message.Invocation;
import net.smc.core.message.Leave;
import net.smc.core.message.Message;
import net.smc.core.message.MessageType;
import net.smc.core.message.PolicyReply;
import net.smc.core.message.PolicyRequest;
import net.smc.core.message.RoleAssignment;
import net.smc.core.message.SharedDecodes;
import net.smc.core.message.InvocationResult;
import net.smc.core.message.CellRequest;
import net.smc.core.message.RoleEvent;
import net.smc.core.message.SubtreeReport;
import net.smc.core.role.Caller;
import net.smc.core.role.ExternalCallException;
import net.smc.core.message.Roster;
import net.smc.core.message.Status;
import net.smc.core.message.Withdrawal;
import net.smc.core.mission.Mission;
import net.smc.core.role.RoleLoadException;
import net.smc.core.router.MessageRouter;
import net.smc.core.security.Credential;
import net.smc.core.transport.Address;
import net.smc.core.transport.Cancellable;

/**
 * The team protocols of one cell: management-tree formation and role assignment (the paper's
 * Algorithms 1 and 2), heartbeats and leases, failure detection and re-assignment, backup
 * commanders, merging of partitioned teams, graceful leave. Sans-IO: it acts only on messages the
 * Message-Router dispatches to it and on its own tick, on the cell's thread.
 *
 * <p>This class wires the parts and owns the life cycle; each part owns its messages:
 * {@link Recruiter} (discovery and assignment as a manager), {@link Assignee} (the vehicle's side of
 * discovery and assignment), {@link Membership} (heartbeats, lease and leave as a child),
 * {@link Supervisor} (children's heartbeats, failures, re-assignment), {@link BackupCommander}
 * (roster and take-over), {@link Merge} (commanders that meet), {@link Reports} (subtree reports and
 * views); they share a {@link TeamContext} and a {@link TeamState}. {@link #register} gives each
 * message type to the one part that handles it, in the cell's {@link MessageRouter}.
 *
 * <p>Policies decide, the parts carry out: a discovery reply becomes a {@code newUAV} event and the
 * role-assignment policy (Table I) asks {@link #requestFullCapability}; a silent child becomes a
 * {@code UAVFailure} event and the re-assignment policy (Table II) asks {@link #reassign}. The rules
 * of seats, identities and priorities are {@link Slots}'; the times are {@link Timing}'s. See
 * <a href="doc-files/team-protocols.md">the team-protocols design note</a>.
 */
final class TeamProtocol implements DiscoveryActions {

    /** What the protocol needs of the rest of its cell. */
    interface Host {
        /** Raises an event into the cell's policy engine. */
        void raise(String event, Object... values);

        /** Loads a role, all or nothing; the exception names the part that failed and why. */
        void loadRole(String role, PolicyStore store) throws RoleLoadException;

        /** Withdraws a role if it is loaded. */
        void withdrawRole(String role);

        /** The credential a peer authenticated with; empty when it presented none or the cell does not authenticate. */
        Optional<Credential> credentialOf(String vehicle);

        /**
         * Checks the datagram the transport held unchecked from {@code from} ({@code
         * AuthenticatingTransport.checkHeld}); when it passes, its message is handled before this
         * returns. Whether one was held.
         */
        default boolean checkHeld(Address from) {
            return false;
        }

        /**
         * Raises in {@code role} an event another vehicle's role published, with that role as the
         * subject (the role's external interface and authorisations decide).
         *
         * @throws ExternalCallException when it is not required there or is denied
         */
        default void deliver(Caller caller, String role, String event, List<Object> values) {
            throw new ExternalCallException(ExternalCallException.Kind.NO_SUCH_ROLE, "this cell takes no remote events");
        }

        /**
         * Invokes an operation of {@code role} for another vehicle's role, which is the subject.
         *
         * @return the answer, as a PonderTalk value
         * @throws ExternalCallException when it is not offered, denied, or fails
         */
        default Object invoke(Caller caller, String role, String operation, List<Object> args) {
            throw new ExternalCallException(ExternalCallException.Kind.NO_SUCH_ROLE, "this cell takes no remote invocations");
        }

        /**
         * Raises (or sends as {@code selector}) an event another cell forwarded to the object at
         * {@code path}, with the caller's subject; this cell's authorisation policies decide.
         *
         * @throws PonderError or ExternalCallException when it is refused or fails
         */
        default void receiveEvent(Caller caller, String path, String selector, String event, Map<String, Object> attributes) {
            throw new ExternalCallException(ExternalCallException.Kind.NO_SUCH_ROLE, "this cell takes no forwarded events");
        }

        /**
         * Evaluates PonderTalk text another cell sent, with the caller's subject, if this cell's
         * authorisation policies allow it.
         *
         * @return the value of its last statement ({@code printed}: the printed form)
         */
        default Object evaluate(Caller caller, String text, boolean printed) {
            throw new ExternalCallException(ExternalCallException.Kind.NO_SUCH_ROLE, "this cell evaluates nothing for others");
        }

        /**
         * The version of the cell's policies ({@code PolicyEngine.policyVersion()}): it grows whenever
         * what they decide may have changed. Always 0 for a host whose policies never change.
         */
        default long policyVersion() {
            return 0;
        }

        /** Reports an error in the cell's policy engine, as its own errors are. */
        default void report(String error) {
        }

        /** The state of the running tasks worth handing over, as wire values; empty when none. */
        default List<Object> taskStates() {
            return List.of();
        }

        /** Gives this vehicle's tasks the task state handed over with {@code role}. */
        default void importTaskStates(String role, List<Object> handedOver) {
        }
    }

    private final TeamContext ctx;
    private final TeamState st;
    private final long tickPhaseMillis;
    private final Seating seating;
    private final TeamCounts counts;
    private final Merge merge;
    private final BackupCommander backup;
    private final Recruiter recruiter;
    private final Reports reports;
    private final Assignee assignee;
    private final Membership membership;
    private final Supervisor supervisor;
    private final Collaboration collaboration;
    private final CellRequests cellRequests;
    /** What this cell reads of datagrams its authenticating transport has not checked yet. */
    private final UnverifiedReads unverified;
    private Cancellable tickTimer;
    private boolean stopped;

    /**
     * @param tickPhaseMillis delay of the first tick, so that the cells of a team do not tick together
     */
    TeamProtocol(TeamContext ctx, long tickPhaseMillis) {
        this.ctx = ctx;
        this.st = new TeamState(ctx);
        this.tickPhaseMillis = tickPhaseMillis;
        this.seating = new Seating(ctx, st);
        this.counts = new TeamCounts(ctx, st);
        this.merge = new Merge(ctx, st, seating);
        this.backup = new BackupCommander(ctx, st, seating, counts, merge);
        this.recruiter = new Recruiter(ctx, st, seating, counts, backup, this::rediscover, this::roundTripMeasured,
                this::discoverAfresh);
        this.reports = new Reports(ctx, st, counts, recruiter);
        this.assignee = new Assignee(ctx, st, seating, merge, this::discoverNow);
        this.membership = new Membership(ctx, st, seating, counts, backup, reports);
        this.supervisor = new Supervisor(ctx, st, seating, counts, backup, recruiter, merge);
        this.collaboration = new Collaboration(ctx, st, assignee);
        this.cellRequests = new CellRequests(ctx, st, collaboration::nextCall);
        this.unverified = new UnverifiedReads(ctx, assignee, recruiter, () -> stopped);
    }

    /**
     * Registers, for each message type of the team protocols, the part that handles it: one
     * subscriber per type, so the router's dispatch by type is the only dispatch.
     */
    void register(MessageRouter router) {
        route(router, MessageType.DISCOVERY, Discovery.class, assignee::onDiscovery);
        route(router, MessageType.DISCOVERY_REPLY, DiscoveryReply.class, recruiter::onDiscoveryReply);
        route(router, MessageType.CAPABILITY_REQUEST, CapabilityRequest.class, assignee::onCapabilityRequest);
        route(router, MessageType.CAPABILITY_REPLY, CapabilityReply.class, recruiter::onCapabilityReply);
        route(router, MessageType.ROLE_ASSIGNMENT, RoleAssignment.class, assignee::onRoleAssignment);
        route(router, MessageType.ASSIGNMENT_RESPONSE, AssignmentResponse.class, recruiter::onAssignmentResponse);
        route(router, MessageType.POLICY_REQUEST, PolicyRequest.class, recruiter::onPolicyRequest);
        route(router, MessageType.POLICY_REPLY, PolicyReply.class, (env, r) -> {
            assignee.onPolicyReply(env, r);
            recruiter.policyArrived(r.uri());
        });
        route(router, MessageType.HEARTBEAT, Heartbeat.class, supervisor::onHeartbeat);
        route(router, MessageType.STATUS, Status.class, membership::onStatus);
        route(router, MessageType.ECHO, Echo.class, membership::onEcho);
        route(router, MessageType.WITHDRAWAL, Withdrawal.class, recruiter::onWithdrawal);
        route(router, MessageType.SUBTREE_REPORT, SubtreeReport.class, reports::onReport);
        route(router, MessageType.ROLE_EVENT, RoleEvent.class, collaboration::onRoleEvent);
        route(router, MessageType.LEAVE, Leave.class, membership::onLeave);
        route(router, MessageType.ROSTER, Roster.class, backup::onRoster);
        route(router, MessageType.INVOCATION, Invocation.class, collaboration::onInvocation);
        route(router, MessageType.INVOCATION_RESULT, InvocationResult.class, (env, r) -> {
            if (!cellRequests.onResult(env, r)) {
                collaboration.onInvocationResult(env, r);
            }
        });
        route(router, MessageType.CELL_REQUEST, CellRequest.class, cellRequests::onCellRequest);
    }

    /** Shares the decodes of {@link #ignoresUnverified} with the process's other cells (null: none). */
    void shareDecodes(SharedDecodes table) {
        unverified.share(table);
    }

    /** Whether this cell would do nothing with the unchecked message, whoever sent it ({@link UnverifiedReads#ignores}). */
    boolean ignoresUnverified(byte[] data, int offset, int length) {
        return unverified.ignores(data, offset, length);
    }

    /** Whether the transport should hold the payload unchecked for this cell to read first ({@link UnverifiedReads#reads}). */
    boolean readsUnverified(byte[] data, int offset, int length) {
        return unverified.reads(data, offset, length);
    }

    /** A payload held unchecked from {@code from} ({@link UnverifiedReads#onHeld}). */
    void onUnverified(Address from, byte[] datagram) {
        unverified.onHeld(from, datagram);
    }

    /** The router selects by type, so the body is of {@code body}'s class: the cast names, it does not choose. */
    private <M extends Message> void route(MessageRouter router, MessageType type, Class<M> body,
                                           BiConsumer<Envelope, M> handler) {
        router.register(envelope -> {
            if (!stopped && !envelope.sender().equals(ctx.self())) {
                handler.accept(envelope, body.cast(envelope.body()));
            }
        }, type);
    }

    // ---------------------------------------------------------------- life cycle

    /** Starts ticking; as the acting commander when {@code commanding}. */
    void start(boolean commanding) {
        if (commanding) {
            Seat seat = Slots.commanderSeat();
            try {
                ctx.host().loadRole(Mission.COMMANDER, ctx.store());
            } catch (RoleLoadException e) {
                throw new IllegalStateException("'" + ctx.self() + "' cannot act as commander: " + e.getMessage(), e);
            }
            st.acting = true;
            st.epoch = 0;
            st.commander = ctx.self();
            st.seats.add(seat);
            st.linksChanged();
            st.identity = ctx.identityOf(seat);
            seating.recomputeOwnership();
            ctx.emit(CellEvent.Kind.COMMANDING, "acting commander of " + ctx.missionId() + " " + st.identity
                    + ", scheme " + ctx.slots().scheme().name().toLowerCase());
            supervisor.discoverNow();
        }
        tickTimer = ctx.scheduler().schedule(tickPhaseMillis, this::tick);
    }

    /**
     * This cell has just taken a role: as a manager, its policies decide on the vehicles that
     * answered the discovery it sent as the assignment arrived, and it discovers at once unless
     * that discovery's answers may still be coming.
     */
    private void discoverNow() {
        recruiter.takeUpEarlyReplies();
        supervisor.roleStarted();
    }

    /** A discovery reply gave a round trip: the discovery repeat follows the cell's estimate. */
    private void roundTripMeasured() {
        supervisor.roundTripMeasured();
    }

    /** A manager's time of taking only its own share of the free vehicles has ended: it discovers at once. */
    private void discoverAfresh() {
        supervisor.discoverNow();
    }

    /** A seat this cell offered is open again: it discovers at once (at most four times a period). */
    private void rediscover() {
        supervisor.rediscover();
    }

    void stop() {
        stopped = true;
        if (tickTimer != null) {
            tickTimer.cancel();
        }
        supervisor.stop();
        recruiter.stop();
    }

    /** Leaves the team gracefully: tells parent and children, gives up every role, answers no discovery. */
    void leave() {
        st.left = true;
        if (st.parent != null) {
            ctx.send(st.parent.address(), new Leave("leaving the team"));
        }
        ctx.emit(CellEvent.Kind.LEFT, "leaves the team");
        seating.dropEverything("left the team");
        st.acting = false;
        st.linksChanged();
    }

    /** Ready to be discovered again after {@link #leave}. */
    void rejoin() {
        st.left = false;
    }

    private void tick() {
        if (stopped) {
            return;
        }
        st.ticks++;
        long now = ctx.clock().nowMillis();
        membership.asChild(now);
        if (!st.owned.isEmpty() || st.acting) {
            supervisor.asManager(now);
        }
        recruiter.expire(now);
        assignee.expire(now);
        tickTimer = ctx.scheduler().schedule(ctx.timing().comTimeoutMillis(), this::tick);
    }

    // ---------------------------------------------------------------- asked by policies and tasks

    /** Asked by a policy ({@code root/discovery fullCapReq: uav role: r}): request the full description. */
    @Override
    public void requestFullCapability(String uav, String role) {
        recruiter.requestFullCapability(uav, role);
    }

    /**
     * Asked by a policy ({@code root/discovery hold} or {@code resume}): while held, this cell as a
     * manager sends no discovery broadcast and takes up no reply to one sent before, so it recruits
     * no one; on resume it discovers at once,
     * as a manager whose role has just started does.
     */
    @Override
    public void holdRecruiting(boolean held) {
        st.recruitingHeld = held;
        if (!held) {
            supervisor.discoverNow();
        }
    }

    @Override
    public boolean recruitingHeld() {
        return st.recruitingHeld;
    }

    /** Asked by a policy ({@code root/role/<manager> reassign: role scheme: s}): find the role a new holder. */
    void reassign(String managingRole, String role, String scheme) {
        supervisor.reassign(managingRole, role, scheme);
    }

    /** Sets the state this vehicle reports to its parent (its position, say), handed over if it fails. */
    void reportState(List<Object> state) {
        reports.reportState(state);
    }

    // ---------------------------------------------------------------- views

    /** Publishes an event of {@code role} to the roles of other vehicles that subscribe to it. */
    int publish(String role, String event, List<Object> values) {
        return collaboration.publish(role, event, values);
    }

    /** Invokes an operation of {@code role} on the vehicle that holds it; the answer is raised as {@code remoteResult}. */
    long invoke(String callerRole, String role, String operation, List<Object> args) {
        return collaboration.invoke(callerRole, role, operation, args);
    }

    /** Sends a request to another cell of the team; the answer is raised as {@code remoteResult}. */
    long request(CellRequest.Kind kind, String cell, String path, String selector, String event, Object value) {
        return cellRequests.send(kind, cell, path, selector, event, value);
    }

    List<Object> handedOver() {
        return reports.handedOver();
    }

    Map<String, Integer> subtreeCounts() {
        return counts.subtreeCounts();
    }

    boolean acting() {
        return st.acting;
    }

    boolean suspended() {
        return st.suspended();
    }

    long epoch() {
        return st.epoch;
    }

    Optional<String> parent() {
        return reports.parent();
    }

    List<Seat> seats() {
        return reports.seats();
    }

    boolean holdsSeats(List<Seat> seats) {
        return reports.holdsSeats(seats);
    }

    String parentOrNull() {
        return reports.parentOrNull();
    }

    long linkVersion() {
        return st.linkVersion.getAsLong();
    }

    void onLinksChanged(Runnable listener) {
        st.linkVersion.listener = listener;
    }

    long leaseUntilMillis() {
        return st.leaseUntilMillis;
    }

    Optional<Identity> identity() {
        return reports.identity();
    }

    Map<String, List<Seat>> children() {
        return reports.children();
    }

    boolean hasChild(String vehicle) {
        return reports.hasChild(vehicle);
    }

    Optional<String> commander() {
        return reports.commander();
    }

    Optional<MissionState> missionState() {
        return reports.missionState();
    }

    /** Messages refused, by reason. */
    Map<String, Long> rejected() {
        return ctx.rejected();
    }

    boolean left() {
        return st.left;
    }

    CellView view() {
        return reports.view();
    }
}
