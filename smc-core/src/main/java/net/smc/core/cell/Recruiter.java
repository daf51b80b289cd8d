package net.smc.core.cell;

import java.math.BigDecimal;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.function.Predicate;

import net.smc.core.capability.CapabilityDescription;
import net.smc.core.capability.CapabilitySummary;
import net.smc.core.cell.TeamState.Child;
import net.smc.core.cell.TeamState.Heard;
import net.smc.core.cell.TeamState.Owned;
import net.smc.core.cell.TeamState.PendingCapability;
import net.smc.core.cell.TeamState.Refusal;
import net.smc.core.comm.DeliveryListener;
import net.smc.core.comm.FailureReason;
import net.smc.core.message.AssignmentResponse;
import net.smc.core.message.CapabilityReply;
import net.smc.core.message.CapabilityRequest;
import net.smc.core.message.DiscoveryReply;
import net.smc.core.message.Envelope;
import net.smc.core.message.Invocation;
import net.smc.core.message.PolicyRequest;
import net.smc.core.message.RoleAssignment;
import net.smc.core.message.Withdrawal;
import net.smc.policy.api.Nil;
import net.smc.core.transport.Address;

/**
 * Discovery and role assignment as a manager (the paper's Algorithms 1 and 2, the parent's side):
 * hears discovery replies and raises {@code newUAV} (Table I), gives seats (taking a hosted one back
 * from its host first), and settles the answers. Serves policy files to assignees, and sends a new
 * assignee the files of its role and of the roles it manages right after its assignment.
 *
 * <p>When the policies ask for a vehicle's full description while deciding on its discovery reply
 * ({@code fullCapReq}), the seat is chosen at once from the capability summary that reply carried:
 * a seat's requirement reads only the vehicle's resources and task names
 * ({@link net.smc.core.capability.CapabilityRequirement#isMetBy(CapabilityDescription)} reads the
 * description's summary), and the reply came from the vehicle itself under its own authentication
 * (signed with its credential, or MAC'd under the session with it), as a capability reply does. The
 * request and its reply would add a round trip to every level of the management tree and decide
 * nothing more. A request asked for outside such a decision still goes out.
 *
 * <p>Owns DISCOVERY_REPLY, CAPABILITY_REPLY, ASSIGNMENT_RESPONSE (settled by {@link AssignmentAnswers}) and
 * POLICY_REQUEST.
 */
final class Recruiter {
    private final TeamContext ctx;
    private final TeamState st;
    private final Seating seating;
    private final TeamCounts counts;
    private final BackupCommander backup;
    /** The vehicle whose {@code newUAV} the policies are deciding on now, or null. */
    private String deciding;
    /** Whether the policies asked for {@link #deciding}'s full description while deciding. */
    private boolean askedFor;
    /** The roles the policies asked for {@link #deciding}'s description for: its seat is chosen among them. */
    private final Set<String> decidedRoles = new LinkedHashSet<>();

    /** Discovers at once (rate-limited by Supervisor), when a seat offered to a vehicle opens again. */
    private final Runnable rediscover;
    /** Serves policy files to assignees and children. */
    private final PolicyServer policies;
    /** How many vehicles are asked for their full descriptions at a time. */
    private final CapabilityAsks asks;
    /** The discovery replies decided on together: a burst, those that came while the role was loading. */
    private final ReplyBatches batches;
    /** The answers to this cell's role assignments. */
    private final AssignmentAnswers answers;

    /** Told when a discovery reply gave the sender a round trip (Supervisor re-times its discovery repeat). */
    private final Runnable measured;

    /**
     * @param rediscover     discovers again, within the rate limit of rediscoveries
     * @param measured       told when a discovery reply gave its sender a round trip
     * @param discoverAfresh discovers at once: when a manager's time of taking its own share only ends
     */
    Recruiter(TeamContext ctx, TeamState st, Seating seating, TeamCounts counts, BackupCommander backup, Runnable rediscover,
              Runnable measured, Runnable discoverAfresh) {
        this.rediscover = rediscover;
        this.measured = measured;
        this.policies = new PolicyServer(ctx, st);
        this.asks = new CapabilityAsks(ctx, st);
        this.batches = new ReplyBatches(ctx, st, this::decide, measured, discoverAfresh);
        this.answers = new AssignmentAnswers(ctx, st, counts, backup, this::lookAgain);
        this.ctx = ctx;
        this.st = st;
        this.seating = seating;
        this.counts = counts;
        this.backup = backup;
    }

    void onDiscoveryReply(Envelope env, DiscoveryReply r) {
        if ((st.owned.isEmpty() && st.incoming == null) || !r.mission().equals(ctx.missionId())) {
            return;
        }
        if (!r.summary().vehicle().equals(env.sender())) {
            ctx.reject(env, "capability summary names vehicle '" + r.summary().vehicle() + "'");
            return;
        }
        if (!st.discoveries.answersOurs(r.inReplyTo())) {
            ctx.reject(env, "answers message " + r.inReplyTo() + ", none of this cell's latest discoveries");
            return;
        }
        long now = ctx.clock().nowMillis();
        st.heard.put(env.sender(), new Heard(r.summary(), r.holds(), now));
        if (batches.isChecking(env.sender())) {
            return; // a held reply checked now: who asked for the check decides on it, and measures it
        }
        // A reply the transport checked as it came: its round trip to the discovery it answers.
        if (ctx.address(env.sender()).filter(a -> st.discoveries.measure(ctx.comm(), a, r.inReplyTo(), now)).isPresent()) {
            measured.run();
        }
        if (st.owned.isEmpty()) {
            // An answer to the discovery sent as the assignment arrived: the role's policies decide on
            // it once the role has started (takeUpEarlyReplies).
            st.earlyReplies.add(env.sender());
            return;
        }
        batches.add(env.sender());
    }

    /**
     * A vehicle that answered one of this cell's discoveries is taking a role from another manager
     * (checked: most often the datagram held from that vehicle in place of its answer, checked as
     * this manager came to it): its answer no longer holds, and is forgotten.
     */
    void onWithdrawal(Envelope env, Withdrawal w) {
        if (w.mission().equals(ctx.missionId()) && st.discoveries.answersOurs(w.inReplyTo())) {
            st.forgetAnswer(env.sender());
            st.earlyReplies.remove(env.sender());
            st.seatGivenTo(env.sender()).ifPresent(seat -> answers.assignmentFailed(env.sender(), seat,
                    "withdrew its answer: it is taking a role from another manager"));
        }
    }

    /**
     * A withdrawal held unchecked from a vehicle that claims to be {@code claimed}. Held, it waits
     * until this manager comes to that vehicle; but if a seat is already on its way to the vehicle
     * (the assignment went out before the withdrawal came), the vehicle will refuse it, and the
     * refusal, a round trip later, may be lost and wait for its timeout: so the withdrawal is checked
     * now, and if it passes, the seat is open again at once ({@link #onWithdrawal}). A forged one
     * costs one check and changes nothing.
     */
    void onUnverifiedWithdrawal(String claimed, Address from, Withdrawal w) {
        if (w.mission().equals(ctx.missionId()) && st.discoveries.answersOurs(w.inReplyTo()) && st.seatGivenTo(claimed).isPresent()) {
            ctx.host().checkHeld(from);
        }
    }

    /** A discovery reply the transport holds unchecked ({@link ReplyBatches#addUnchecked}). */
    void onUnverifiedReply(String claimed, Address from, DiscoveryReply r) {
        batches.addUnchecked(claimed, from, r);
    }

    /**
     * Checks held replies until one passes that {@code wanted} accepts ({@link ReplyBatches#checkUntil}):
     * for Supervisor's reassignment and swaps, which read the free vehicles heard of. Whether one was found.
     */
    boolean checkUntil(long windowMillis, Predicate<Heard> wanted) {
        return batches.checkUntil(windowMillis, wanted);
    }

    /** The role this cell was taking has started: its policies decide on the vehicles that answered meanwhile. */
    void takeUpEarlyReplies() {
        batches.takeUpEarly();
    }

    /** The cell stops: replies not yet decided on are dropped. */
    void stop() {
        batches.stop();
    }

    /** Table I and Algorithm 2 on a free vehicle that answered discovery with {@code summary}. */
    private void decide(String vehicle, CapabilitySummary summary, long now) {
        if (st.children.containsKey(vehicle) || !st.hasVacancy() || st.recruitingHeld) {
            return; // held: a policy keeps this manager from recruiting, replies to an earlier discovery included
        }
        // Table I decides whom to ask: newUAV(name uav lowLevelCap credential).
        // A vehicle that presented no credential (or a cell without authentication) gives PonderTalk nil.
        Object credential = ctx.host().credentialOf(vehicle).<Object>map(c -> c).orElse(Nil.NIL);
        Refusal before = st.refused.get(vehicle);
        if (before != null && before.stands(st.refusal(summary, credential, now), ctx.timing().refusalMillis())) {
            return; // the same policies passed over the same vehicle for the same open seats: they would again
        }
        st.refused.remove(vehicle);
        deciding = vehicle;
        askedFor = false;
        decidedRoles.clear();
        try {
            ctx.host().raise("newUAV", "newUAV", vehicle, summary, credential);
        } finally {
            deciding = null;
        }
        if (!askedFor) {
            // Taken after the raise: a change the policies made while deciding is part of their decision.
            st.refused.put(vehicle, st.refusal(summary, credential, now));
        } else if (!decidedRoles.isEmpty()) {
            Set<String> roles = new LinkedHashSet<>(decidedRoles);
            decidedRoles.clear();
            seatFromSummary(vehicle, summary, credential, roles);
        }
    }

    /**
     * Algorithm 2 (line 3 on) for a vehicle the policies asked for while deciding on its discovery
     * reply: the best open seat of the roles they asked for whose requirement the reply's summary
     * meets (vacant first, then by priority, as for a capability reply) goes to it now.
     */
    private void seatFromSummary(String uav, CapabilitySummary summary, Object credential, Set<String> roles) {
        Heard heard = st.heard.get(uav);
        Optional<Seat> seat = st.owned.keySet().stream()
                .filter(s -> roles.contains(s.role()) && st.open(s))
                .filter(s -> ctx.slots().role(s.role()).requirement().isMetBy(summary))
                .filter(s -> heard == null || TeamState.couldTake(heard, s.role(), ctx.slots()))
                .min(this::preferVacant);
        if (seat.isEmpty()) {
            // No seat asked for that the vehicle can take: while the same stands, none would be found again.
            st.refused.put(uav, st.refusal(summary, credential, ctx.clock().nowMillis()));
            return;
        }
        if (st.seatGivenTo(uav).isPresent()) {
            return; // already being given a seat
        }
        giveSeat(uav, summary, seat.get());
    }

    /** Asked by a policy ({@code root/discovery fullCapReq: uav role: r}): request the full description. */
    void requestFullCapability(String uav, String role) {
        if (ctx.slots().mission().role(role).isEmpty()) {
            ctx.emit(CellEvent.Kind.REJECTED, "policy asked for unknown role '" + role + "' for " + uav);
            return;
        }
        if (asks.openSeats(role) == 0) {
            return; // nothing to give for that role now
        }
        st.refused.remove(uav);
        if (uav.equals(deciding)) {
            askedFor = true;
            decidedRoles.add(role); // its discovery reply's summary decides, once the policies are done
            return;
        }
        PendingCapability pending = st.capabilityRequests.get(uav);
        if (pending != null) {
            pending.roles.add(role);
            return;
        }
        if (asks.full(role)) {
            asks.defer(uav, role);
            return; // enough vehicles asked for this role's open seats: this one waits its turn
        }
        Optional<Address> to = ctx.address(uav);
        if (to.isEmpty()) {
            return;
        }
        PendingCapability asked = new PendingCapability(ctx.clock().nowMillis());
        asked.roles.add(role);
        st.capabilityRequests.put(uav, asked);
        ctx.comm().send(to.get(), new CapabilityRequest(role), TeamContext.failureOnly(() -> {
            if (st.capabilityRequests.remove(uav, asked)) {
                lookAgain();
            }
        }));
    }

    /**
     * A request or assignment out ended without filling a seat: asks the vehicles waiting their
     * turn, puts the free vehicles that answered discovery lately to the policies again, else
     * discovers again.
     */
    private void lookAgain() {
        askDeferred();
        batches.decideOnHeard();
        rediscover.run();   // does nothing while requests are out or no seat is open: their ends look again
    }

    private void askDeferred() {
        asks.askDeferred(this::requestFullCapability);
    }

    void onCapabilityReply(Envelope env, CapabilityReply r) {
        settleCapabilityReply(env, r);
        askDeferred();   // a seat given or not, the requests out for its role are one fewer
    }

    private void settleCapabilityReply(Envelope env, CapabilityReply r) {
        PendingCapability pending = st.capabilityRequests.remove(env.sender());
        if (pending == null || st.recruitingHeld) {
            return;
        }
        CapabilityDescription full = r.description();
        if (!full.vehicle().equals(env.sender())) {
            ctx.reject(env, "capability description names vehicle '" + full.vehicle() + "'");
            return;
        }
        Child known = st.children.get(env.sender());
        if (known != null && !known.seats.isEmpty()) {
            known.description = full.summary(); // a child (from a roster, say): now this cell knows what it can do
            return;
        }
        // Algorithm 2, line 3: the description must match the requirement of one of the roles (and a
        // vehicle that holds a role elsewhere takes only one ranked before it).
        Heard answered = st.heard.get(env.sender());
        Optional<Seat> seat = st.owned.keySet().stream()
                .filter(s -> pending.roles.contains(s.role()) && st.open(s))
                .filter(s -> ctx.slots().role(s.role()).requirement().isMetBy(full))
                .filter(s -> answered == null || TeamState.couldTake(answered, s.role(), ctx.slots()))
                .min(this::preferVacant);
        if (seat.isEmpty()) {
            // Algorithm 2 found no seat asked for that the vehicle can take: while the same stands,
            // asking again would find none again.
            Heard heard = st.heard.get(env.sender());
            if (heard != null && known == null) {
                Object credential = ctx.host().credentialOf(env.sender()).<Object>map(c -> c).orElse(Nil.NIL);
                st.refused.put(env.sender(), st.refusal(heard.summary(), credential, ctx.clock().nowMillis()));
            }
            return;
        }
        if (st.seatGivenTo(env.sender()).isPresent()) {
            return; // already being given a seat
        }
        giveSeat(env.sender(), full.summary(), seat.get());
    }

    /** Vacant seats first, then seats a vehicle of another role hosts; by priority. */
    private int preferVacant(Seat a, Seat b) {
        int c = Boolean.compare(st.owned.get(a).holder != null, st.owned.get(b).holder != null);
        return c != 0 ? c : ctx.slots().compare(a, b);
    }

    /** Gives {@code seat} to {@code vehicle}, releasing it from a host first. */
    void giveSeat(String vehicle, CapabilitySummary full, Seat seat) {
        Owned o = st.owned.get(seat);
        if (o.holder != null) {
            String hostVehicle = o.holder;
            o.pendingFor = vehicle;
            o.pendingSince = ctx.clock().nowMillis();
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
        if (holder.equals(ctx.self())) {
            seating.dropOwnSeat(seat, "makes way for a vehicle of its own");
            st.owned.get(seat).holder = null;
            then.run();
            return;
        }
        Child child = st.children.get(holder);
        if (child == null) {
            st.owned.get(seat).holder = null;
            then.run();
            return;
        }
        ctx.comm().send(child.address, new Invocation(seat.role(), "release", List.of(BigDecimal.valueOf(seat.slot()))),
                new DeliveryListener() {
                    @Override
                    public void delivered(long id) {
                        Child c = st.children.get(holder);
                        if (c != null) {
                            c.seats = c.seats.stream().filter(s -> !s.equals(seat)).toList();
                            st.linksChanged();
                        }
                        Owned o = st.owned.get(seat);
                        if (o != null && holder.equals(o.holder)) {
                            o.holder = null;
                        }
                        then.run();
                    }

                    @Override
                    public void failed(long id, FailureReason reason) {
                        Owned o = st.owned.get(seat);
                        if (o != null) {
                            o.pendingFor = null;
                        }
                    }
                });
    }

    /** Sends the role assignment (Algorithm 1, lines 6 and 15, once accepted). */
    void assign(String vehicle, CapabilitySummary full, Seat seat) {
        Optional<Address> to = ctx.address(vehicle);
        Owned o = st.owned.get(seat);
        if (to.isEmpty() || o == null) {
            return;
        }
        List<Object> state = st.handover.getOrDefault(seat.role(), List.of());
        Child child = st.children.computeIfAbsent(vehicle, Child::new);
        st.linksChanged();
        RoleAssignment assignment = new RoleAssignment(ctx.missionId(), seat.role(), ctx.identityOf(seat), ctx.self(),
                ctx.policyRefs(seat.role()), st.epoch, state, child.seats.stream().map(Seat::toString).toList(), st.ancestors);
        o.pendingFor = vehicle;
        o.pendingSince = ctx.clock().nowMillis();
        child.address = to.get();
        child.description = full;
        if (child.seats.isEmpty()) {
            child.lastHeard = ctx.clock().nowMillis();
        }
        ctx.emit(CellEvent.Kind.ASSIGNING, seat + " " + ctx.identityOf(seat) + " to " + vehicle
                + (state.isEmpty() ? "" : " with handed-over state " + state));
        boolean holdsRole = child.seats.stream().anyMatch(s -> s.role().equals(seat.role()));
        // Not delivered is not proof of not received (the Acks may be lost): the reservation stays
        // until it expires, an answer comes, or the vehicle's heartbeat shows it took the seat.
        long id = ctx.comm().send(to.get(), assignment, TeamContext.failureOnly(() -> ctx.emit(CellEvent.Kind.ASSIGNMENT_FAILED, seat + " to "
                + vehicle + ": not acknowledged; the seat stays reserved until an answer or "
                + ctx.pendingMillis() + " ms")));
        if (!holdsRole) {
            policies.sendWithAssignment(to.get(), seat.role(), id);
        }
    }

    void onAssignmentResponse(Envelope env, AssignmentResponse r) {
        answers.onAssignmentResponse(env, r);
    }

    /** The vehicle took the seat: it is now a child holding it ({@link AssignmentAnswers#accepted}). */
    void accepted(String vehicle, Seat seatTaken) {
        answers.accepted(vehicle, seatTaken);
    }

    void onPolicyRequest(Envelope env, PolicyRequest r) {
        policies.onPolicyRequest(env, r);
    }

    /** A policy file arrived: answers the children's requests that waited for it. */
    void policyArrived(String uri) {
        policies.policyArrived(uri);
    }

    /** Drops stale requests and reservations, and reports each reservation that expired. */
    /**
     * Drops the entries of {@code map} whose values are {@code stale}. Every cell ticks twice a second
     * and these maps are mostly empty once a team has formed: an empty one is passed over without the
     * iterator and predicate a {@code removeIf} allocates (and without walking the table a map keeps at
     * the size it grew to while the team formed).
     */
    private static <V> void dropIf(Map<?, V> map, Predicate<? super V> stale) {
        if (!map.isEmpty()) {
            map.values().removeIf(stale);
        }
    }

    void expire(long now) {
        dropIf(st.abandoned, until -> now >= until);
        dropIf(st.capabilityRequests, p -> now - p.sinceMillis > ctx.timing().failureTimeoutMillis());
        dropIf(st.heard, h -> now - h.atMillis() > 4 * ctx.timing().failureTimeoutMillis());
        dropIf(st.unchecked, u -> now - u.atMillis() > 4 * ctx.timing().failureTimeoutMillis());
        dropIf(st.refused, r -> now - r.atMillis() >= ctx.timing().refusalMillis());
        policies.expire(now);
        for (Map.Entry<Seat, Owned> e : st.owned.entrySet()) {
            Owned o = e.getValue();
            if (o.pendingFor != null && now - o.pendingSince > ctx.pendingMillis()) {
                answers.assignmentFailed(o.pendingFor, e.getKey(), "no answer within " + ctx.pendingMillis() + " ms");
            }
        }
    }
}
