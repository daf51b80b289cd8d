package net.smc.core.cell;

import java.math.BigDecimal;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;

import net.smc.core.capability.CapabilityDescription;
import net.smc.core.capability.CapabilitySummary;
import net.smc.core.cell.TeamState.Child;
import net.smc.core.cell.TeamState.Heard;
import net.smc.core.cell.TeamState.Owned;
import net.smc.core.cell.TeamState.ParkedRequest;
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
import net.smc.core.message.Leave;
import net.smc.core.message.PolicyReply;
import net.smc.core.message.PolicyRequest;
import net.smc.core.message.RoleAssignment;
import net.smc.policy.api.Nil;
import net.smc.core.transport.Address;

/**
 * Discovery and role assignment as a manager (the paper's Algorithms 1 and 2, the parent's side):
 * hears discovery replies and raises {@code newUAV} (Table I), asks for full capability
 * descriptions, gives seats (taking a hosted one back from its host first), and settles the answers.
 * Serves policy files to assignees. Owns DISCOVERY_REPLY, CAPABILITY_REPLY, ASSIGNMENT_RESPONSE and
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

    /**
     * How many capability requests for a role may be out beyond its open seats. A manager asks no
     * more vehicles than it could seat and this margin (for those that turn out taken or unable):
     * in a large team every free vehicle in reach answers every manager's discovery, and asking
     * each of them costs both a request and a full description for a seat most will not get. The
     * others wait in {@link TeamState#deferredAsks} and are asked as requests out end unseated.
     */
    static final int ASK_MARGIN = 2;

    /** Discovers at once (rate-limited by Supervisor), when a seat offered to a vehicle opens again. */
    private final Runnable rediscover;

    Recruiter(TeamContext ctx, TeamState st, Seating seating, TeamCounts counts, BackupCommander backup, Runnable rediscover) {
        this.rediscover = rediscover;
        this.ctx = ctx;
        this.st = st;
        this.seating = seating;
        this.counts = counts;
        this.backup = backup;
    }

    void onDiscoveryReply(Envelope env, DiscoveryReply r) {
        if (st.owned.isEmpty() || !r.mission().equals(ctx.missionId())) {
            return;
        }
        if (!r.summary().vehicle().equals(env.sender())) {
            ctx.reject(env, "capability summary names vehicle '" + r.summary().vehicle() + "'");
            return;
        }
        long now = ctx.clock().nowMillis();
        st.heard.put(env.sender(), new Heard(r.summary(), now));
        if (st.children.containsKey(env.sender()) || !st.hasVacancy() || st.recruitingHeld) {
            return; // held: a policy keeps this manager from recruiting, replies to an earlier discovery included
        }
        // Table I decides whom to ask: newUAV(name uav lowLevelCap credential).
        // A vehicle that presented no credential (or a cell without authentication) gives PonderTalk nil.
        Object credential = ctx.host().credentialOf(env.sender()).<Object>map(c -> c).orElse(Nil.NIL);
        Refusal before = st.refused.get(env.sender());
        if (before != null && before.stands(refusal(r.summary(), credential, now), refusalMillis())) {
            return; // the same policies passed over the same vehicle for the same open seats: they would again
        }
        st.refused.remove(env.sender());
        deciding = env.sender();
        askedFor = false;
        try {
            ctx.host().raise("newUAV", "newUAV", env.sender(), r.summary(), credential);
        } finally {
            deciding = null;
        }
        if (!askedFor) {
            // Taken after the raise: a change the policies made while deciding is part of their decision.
            st.refused.put(env.sender(), refusal(r.summary(), credential, now));
        }
    }

    /** The key of a refusal now: what the vehicle presented, the policies' version and this cell's open seats. */
    private Refusal refusal(CapabilitySummary summary, Object credential, long now) {
        return new Refusal(summary, credential, ctx.host().policyVersion(),
                st.owned.keySet().stream().filter(st::open).toList(), now);
    }

    /**
     * How long a refusal is remembered at most: four failure timeouts (12 s in the reconnaissance
     * mission). Within it a free vehicle that keeps answering discovery is put to the policies
     * again only when what it presents (capability summary, credential), the policies (their
     * version) or this cell's open seats change; the bound covers conditions that read other state
     * (counts, the time, what a task observed).
     */
    long refusalMillis() {
        return 4 * ctx.timing().failureTimeoutMillis();
    }

    /** Asked by a policy ({@code root/discovery fullCapReq: uav role: r}): request the full description. */
    void requestFullCapability(String uav, String role) {
        if (ctx.slots().mission().role(role).isEmpty()) {
            ctx.emit(CellEvent.Kind.REJECTED, "policy asked for unknown role '" + role + "' for " + uav);
            return;
        }
        if (st.owned.keySet().stream().noneMatch(s -> s.role().equals(role) && st.open(s))) {
            return; // nothing to give for that role now
        }
        if (uav.equals(deciding)) {
            askedFor = true;
        }
        st.refused.remove(uav);
        PendingCapability pending = st.capabilityRequests.get(uav);
        if (pending != null) {
            pending.roles.add(role);
            return;
        }
        if (asksOut(role) >= openSeats(role) + ASK_MARGIN) {
            st.deferredAsks.computeIfAbsent(uav, v -> new LinkedHashSet<>()).add(role);
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

    private long openSeats(String role) {
        return st.owned.keySet().stream().filter(s -> s.role().equals(role) && st.open(s)).count();
    }

    private long asksOut(String role) {
        return st.capabilityRequests.values().stream().filter(p -> p.roles.contains(role)).count();
    }

    /** A request out ended without filling a seat: asks the vehicles waiting their turn, else discovers again. */
    private void lookAgain() {
        askDeferred();
        rediscover.run();   // does nothing while requests are out: their ends look again
    }

    /**
     * Asks deferred vehicles, oldest first, as far as the margin allows; forgets those that are now
     * children, already asked, or not heard within the failure timeout, and roles with no open seat.
     */
    private void askDeferred() {
        long now = ctx.clock().nowMillis();
        for (String uav : List.copyOf(st.deferredAsks.keySet())) {
            Heard heard = st.heard.get(uav);
            if (heard == null || now - heard.atMillis() > ctx.timing().failureTimeoutMillis()
                    || st.children.containsKey(uav) || st.capabilityRequests.containsKey(uav)) {
                st.deferredAsks.remove(uav);
                continue;
            }
            Set<String> roles = st.deferredAsks.get(uav);
            for (String role : List.copyOf(roles)) {
                long open = openSeats(role);
                if (open == 0) {
                    roles.remove(role);
                } else if (asksOut(role) < open + ASK_MARGIN) {
                    roles.remove(role);
                    requestFullCapability(uav, role);
                }
            }
            if (roles.isEmpty()) {
                st.deferredAsks.remove(uav);
            }
        }
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
            known.description = full; // a child (from a roster, say): now this cell knows what it can do
            return;
        }
        // Algorithm 2, line 3: the description must match the requirement of one of the roles.
        Optional<Seat> seat = st.owned.keySet().stream()
                .filter(s -> pending.roles.contains(s.role()) && st.open(s))
                .filter(s -> ctx.slots().role(s.role()).requirement().isMetBy(full))
                .min(this::preferVacant);
        if (seat.isEmpty()) {
            // Algorithm 2 found no seat asked for that the vehicle can take: while the same stands,
            // asking again would find none again.
            Heard heard = st.heard.get(env.sender());
            if (heard != null && known == null) {
                Object credential = ctx.host().credentialOf(env.sender()).<Object>map(c -> c).orElse(Nil.NIL);
                st.refused.put(env.sender(), refusal(heard.summary(), credential, ctx.clock().nowMillis()));
            }
            return;
        }
        if (st.owned.values().stream().anyMatch(o -> env.sender().equals(o.pendingFor))) {
            return; // already being given a seat
        }
        giveSeat(env.sender(), full, seat.get());
    }

    /** Vacant seats first, then seats a vehicle of another role hosts; by priority. */
    private int preferVacant(Seat a, Seat b) {
        int c = Boolean.compare(st.owned.get(a).holder != null, st.owned.get(b).holder != null);
        return c != 0 ? c : ctx.slots().compare(a, b);
    }

    /** Gives {@code seat} to {@code vehicle}, releasing it from a host first. */
    void giveSeat(String vehicle, CapabilityDescription full, Seat seat) {
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
    void assign(String vehicle, CapabilityDescription full, Seat seat) {
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
        // Not delivered is not proof of not received (the Acks may be lost): the reservation stays
        // until it expires, an answer comes, or the vehicle's heartbeat shows it took the seat.
        ctx.comm().send(to.get(), assignment, TeamContext.failureOnly(() -> ctx.emit(CellEvent.Kind.ASSIGNMENT_FAILED, seat + " to "
                + vehicle + ": not acknowledged; the seat stays reserved until an answer or "
                + ctx.pendingMillis() + " ms")));
    }

    void onAssignmentResponse(Envelope env, AssignmentResponse r) {
        String vehicle = env.sender();
        Optional<Seat> seat = st.owned.entrySet().stream()
                .filter(e -> vehicle.equals(e.getValue().pendingFor) && e.getKey().role().equals(r.role()))
                .map(Map.Entry::getKey).findFirst();
        if (seat.isEmpty() && !r.accepted() && st.capabilityRequests.remove(vehicle) != null) {
            // The vehicle declined a capability request: it took a seat from another manager since it
            // answered discovery. The request no longer holds rediscovery back; look again now.
            lookAgain();
            return;
        }
        if (seat.isEmpty()) {
            Child child = st.children.get(vehicle);
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
        Child c = st.children.get(vehicle);
        if (c != null) {
            c.confirmedBy.put(seat.get(), env.id());
        }
    }

    /**
     * A vehicle took a seat this cell no longer reserves for it (the reservation expired): it must
     * give the role back, or it would hold a seat that may have gone to another.
     */
    private void revoke(String vehicle, String role) {
        Child child = st.children.get(vehicle);
        Optional<Address> to = ctx.address(vehicle);
        if (to.isEmpty()) {
            return;
        }
        ctx.emit(CellEvent.Kind.REJECTED, vehicle + " took " + role + " after its reservation expired; revoked");
        if (child != null && !child.seats.isEmpty()) {
            ctx.comm().send(to.get(), new Invocation(role, "release", List.of()));
        } else {
            ctx.send(to.get(), new Leave("'" + ctx.self() + "' no longer holds a seat of '" + role + "' for '" + vehicle + "'"));
        }
    }

    /** The vehicle took the seat: it is now a child holding it. */
    void accepted(String vehicle, Seat seatTaken) {
        Optional<Seat> seat = Optional.of(seatTaken);
        Owned o = st.owned.get(seat.get());
        o.pendingFor = null;
        o.holder = vehicle;
        Child child = st.children.computeIfAbsent(vehicle, Child::new);
        child.address = ctx.address(vehicle).orElse(child.address);
        child.lastHeard = ctx.clock().nowMillis();
        List<Seat> before = child.seats;
        child.seats = ctx.slots().afterAssign(before, seat.get()).stream().filter(st.owned::containsKey).toList();
        st.linksChanged();
        for (Seat dropped : before) {
            if (!child.seats.contains(dropped) && st.owned.containsKey(dropped) && vehicle.equals(st.owned.get(dropped).holder)) {
                st.owned.get(dropped).holder = null;
            }
        }
        st.handover.remove(seat.get().role());
        st.heard.remove(vehicle);
        ctx.emit(CellEvent.Kind.ASSIGNED, seat.get() + " to " + vehicle + " (now holds " + child.seats + ")");
        backup.sendRosterIfBackup();
        counts.updateMissionState();
    }

    void assignmentFailed(String vehicle, Seat seat, String why) {
        Owned o = st.owned.get(seat);
        if (o == null || !vehicle.equals(o.pendingFor)) {
            return;
        }
        o.pendingFor = null;
        Child child = st.children.get(vehicle);
        if (child != null && child.seats.isEmpty()) {
            st.children.remove(vehicle);
            st.linksChanged();
        }
        ctx.emit(CellEvent.Kind.ASSIGNMENT_FAILED, seat + " to " + vehicle + ": " + why);
        // The seat is open again: look for another vehicle now (one taken by a neighbouring manager,
        // say), not at the next tick.
        lookAgain();
    }

    void onPolicyRequest(Envelope env, PolicyRequest r) {
        Optional<PolicyStore.Entry> entry = ctx.store().get(r.uri(), r.version());
        if (entry.isEmpty() && (st.acting || st.backupRank >= 0)) {
            entry = ctx.fromRepository(r.uri()).filter(e -> r.version() == PolicyStore.ANY_VERSION
                    || e.version() == r.version());
        }
        Optional<Address> back = ctx.address(env.sender());
        if (entry.isEmpty() && back.isPresent() && onItsWay(r.uri())) {
            st.parkedPolicyRequests.computeIfAbsent(r.uri(), u -> new ArrayList<>())
                    .add(new ParkedRequest(back.get(), env.id(), r.version(), ctx.clock().nowMillis()));
            return; // answered when the file arrives (policyArrived)
        }
        if (entry.isEmpty() || back.isEmpty()) {
            ctx.reject(env, "policy " + r.uri() + " version " + r.version() + " is not held here");
            return;
        }
        ctx.comm().send(back.get(), new PolicyReply(env.id(), r.uri(), entry.get().version(), entry.get().text()));
    }

    /**
     * Whether a policy file this cell does not hold is on its way to it: a file of the roles below
     * one it holds, which it fetches from its own manager after taking the role.
     */
    private boolean onItsWay(String uri) {
        return st.parent != null && st.seats.stream().anyMatch(s -> ctx.subtreePolicyUris(s.role()).contains(uri));
    }

    /** A policy file arrived: answers the children's requests that waited for it. */
    void policyArrived(String uri) {
        List<ParkedRequest> parked = st.parkedPolicyRequests.get(uri);
        if (parked == null) {
            return;
        }
        parked.removeIf(p -> {
            Optional<PolicyStore.Entry> entry = ctx.store().get(uri, p.version());
            entry.ifPresent(e -> ctx.comm().send(p.from(), new PolicyReply(p.envelopeId(), uri, e.version(), e.text())));
            return entry.isPresent();
        });
        if (parked.isEmpty()) {
            st.parkedPolicyRequests.remove(uri);
        }
    }

    /** Drops stale requests and reservations, and reports each reservation that expired. */
    void expire(long now) {
        st.abandoned.values().removeIf(until -> now >= until);
        st.capabilityRequests.values().removeIf(p -> now - p.sinceMillis > ctx.timing().failureTimeoutMillis());
        st.heard.values().removeIf(h -> now - h.atMillis() > 4 * ctx.timing().failureTimeoutMillis());
        st.refused.values().removeIf(r -> now - r.atMillis() >= refusalMillis());
        st.parkedPolicyRequests.values().removeIf(parked -> {
            parked.removeIf(p -> now - p.atMillis() > ctx.timing().failureTimeoutMillis());
            return parked.isEmpty();
        });
        for (Map.Entry<Seat, Owned> e : st.owned.entrySet()) {
            Owned o = e.getValue();
            if (o.pendingFor != null && now - o.pendingSince > ctx.pendingMillis()) {
                assignmentFailed(o.pendingFor, e.getKey(), "no answer within " + ctx.pendingMillis() + " ms");
            }
        }
    }
}
