package net.smc.core.cell;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;

import net.smc.core.cell.TeamState.Answered;
import net.smc.core.cell.TeamState.Incoming;
import net.smc.core.cell.TeamState.Parent;
import net.smc.core.message.AssignmentResponse;
import net.smc.core.message.CapabilityReply;
import net.smc.core.message.CapabilityRequest;
import net.smc.core.message.Discovery;
import net.smc.core.message.DiscoveryReply;
import net.smc.core.message.Envelope;
import net.smc.core.message.Invocation;
import net.smc.core.message.Leave;
import net.smc.core.message.PolicyRef;
import net.smc.core.message.PolicyReply;
import net.smc.core.message.PolicyRequest;
import net.smc.core.message.RoleAssignment;
import net.smc.core.message.Withdrawal;
import net.smc.core.mission.Mission;
import net.smc.core.role.RoleLoadException;
import net.smc.core.transport.Address;

/**
 * Discovery and role assignment from the vehicle's side (Algorithm 1, lines 8-15): answers
 * discoveries and capability requests, takes a role assignment once its policies have arrived (or
 * refuses it, saying why), moves up to a role of higher priority, and gives a role back when its
 * parent asks. Owns DISCOVERY (handing a rival commander's beacon to {@link Merge}),
 * CAPABILITY_REQUEST, ROLE_ASSIGNMENT and POLICY_REPLY, and takes a parent's {@code release}
 * from {@link Collaboration}, which owns INVOCATION.
 *
 * <p>The manager sends the role's own policy files right behind the assignment, then those of the
 * roles it manages directly (which this cell sends its children); this cell asks for the files of
 * the roles further down once it has taken the role, for the role's own still missing a heartbeat
 * period after the assignment, and for its children's still missing a heartbeat period after it
 * took the role.
 */
final class Assignee {
    private final TeamContext ctx;
    private final TeamState st;
    private final Seating seating;
    private final Merge merge;
    /** Whether this vehicle could hold a role managed by a manager of the role (the key): see couldHoldAny. */
    private final Map<String, Boolean> couldHold = new HashMap<>();
    /**
     * For a manager's role (the key), the best (lowest) rank of a role it manages that this vehicle
     * is able to hold, {@link Integer#MAX_VALUE} if none: see promotable. Fixed for the cell's life,
     * like {@link #couldHold}; every cell weighs the commander's beacon, every two seconds.
     */
    private final Map<String, Integer> bestHoldableRank = new HashMap<>();
    /** Run when this cell has taken a role: a manager starts discovering its children at once. */
    private final Runnable roleTaken;
    /** The assignment being taken whose missing own files this cell has asked for (expire), or null. */
    private Incoming askedForOwnPolicies;
    /** The role taken whose children's files this cell asks for if they have not come (expire), or null. */
    private SubtreeFetch subtreeFetch;

    /** A role taken at {@code sinceMillis} from {@code manager} (at {@code from}), by assignment {@code assignment}. */
    private record SubtreeFetch(String manager, Address from, RoleAssignment assignment, long sinceMillis) {
    }

    Assignee(TeamContext ctx, TeamState st, Seating seating, Merge merge, Runnable roleTaken) {
        this.ctx = ctx;
        this.st = st;
        this.seating = seating;
        this.merge = merge;
        this.roleTaken = roleTaken;
    }

    void onDiscovery(Envelope env, Discovery d) {
        if (ignores(env.sender(), d)) {
            return;
        }
        if (st.acting && d.role().equals(Mission.COMMANDER)) {
            merge.meetCommander(env.sender(), d.epoch());
            return;
        }
        Optional<Address> to = ctx.address(env.sender());
        if (to.isPresent()) {
            // A vehicle with a parent answers only as a candidate for a role ranked before its own: it says which it holds.
            String holds = st.free() || st.seats.isEmpty() ? "" : st.seats.get(0).role();
            ctx.sendWithoutHandshake(to.get(), new DiscoveryReply(env.id(), ctx.missionId(), holds, ctx.description().summary()));
            long now = ctx.clock().nowMillis();
            long window = ctx.timing().senderSettings().initialTimeoutMillis();
            st.answered.values().removeIf(x -> now - x.atMillis() > window);
            st.answered.put(env.sender(), new Answered(to.get(), env.id(), now));
        }
    }

    /**
     * This free vehicle is taking a role from {@code from}: the other managers whose discoveries it
     * answered within the window in which a manager offers seats on answers (the first
     * retransmission timeout) are told it withdraws them, so that none offers it a seat it would
     * refuse (a round trip each, and a chain of them when siblings race for the last vehicles).
     */
    private void withdrawAnswers(String from) {
        long now = ctx.clock().nowMillis();
        long window = ctx.timing().senderSettings().initialTimeoutMillis();
        for (Map.Entry<String, Answered> e : st.answered.entrySet()) {
            Answered x = e.getValue();
            if (!e.getKey().equals(from) && now - x.atMillis() <= window) {
                ctx.sendWithoutHandshake(x.address(), new Withdrawal(x.discovery(), ctx.missionId()));
            }
        }
        st.answered.clear();
    }

    /**
     * Whether this cell does nothing with discovery {@code d} from {@code sender}, now, whoever
     * really sent it: another mission's; a vehicle with a parent (Algorithm 1, line 9) or that left
     * the team, unless it could move up to a role that manager manages; a vehicle able to hold none
     * of the roles that manager manages. {@link #onDiscovery} answers exactly the others (or meets a
     * rival commander), so the transport may drop such a discovery before checking its signature
     * ({@code AuthenticatingTransport.setUnverifiedFilter}): an authentic one would change nothing,
     * a forged one would be refused. Changes no state but a cache of what the mission lets it hold.
     */
    boolean ignores(String sender, Discovery d) {
        if (!d.mission().equals(ctx.missionId())) {
            return true;
        }
        if (st.acting && d.role().equals(Mission.COMMANDER)) {
            return false; // a rival commander's beacon: the merge meets it
        }
        boolean promotable = st.parent != null && !st.parent.vehicle().equals(sender) && promotable(d.role(), d.epoch());
        if ((!st.free() || st.left) && !promotable) {
            return true; // Algorithm 1, line 9: a vehicle with a parent ignores discovery (unless it could move up)
        }
        return !promotable && !couldHoldAny(d.role()); // the manager could give it no seat
    }

    void onCapabilityRequest(Envelope env, CapabilityRequest r) {
        boolean fromParent = st.parent != null && st.parent.vehicle().equals(env.sender());
        if (!fromParent && (!st.free() || st.left) && !promotion(r.role(), st.epoch)) {
            // Declines, so that the manager asks another vehicle now instead of waiting for an answer
            // that will not come (a request out holds its rediscovery back until it expires).
            ctx.address(env.sender()).ifPresent(a -> ctx.send(a, new AssignmentResponse(env.id(), r.role(), false,
                    st.left ? "this vehicle has left the team" : "this vehicle is no longer free")));
            return;
        }
        ctx.address(env.sender()).ifPresent(a -> ctx.comm().send(a, new CapabilityReply(env.id(), ctx.description())));
    }

    void onRoleAssignment(Envelope env, RoleAssignment a) {
        String from = env.sender();
        Optional<Address> back = ctx.address(from);
        if (back.isEmpty()) {
            return;
        }
        if (from.equals(st.lastAssignmentFrom) && env.id() < st.lastAssignmentId) {
            // Sent before an assignment this cell has already taken (or is taking) from the same
            // manager: the later one is the manager's word. Taking this copy could give this vehicle a
            // seat the manager no longer owns (it has since dropped the role that owned it) and so
            // another vehicle's seat. No answer: one matched by role could settle the later offer.
            ctx.emit(CellEvent.Kind.REJECTED, a.role() + " " + a.identity() + " from " + from
                    + ": sent before the assignment taken from it since; a late copy");
            return;
        }
        String refusal = refusal(from, a);
        if (refusal != null) {
            ctx.emit(CellEvent.Kind.REFUSED, a.role() + " from " + from + ": " + refusal);
            ctx.comm().send(back.get(), new AssignmentResponse(env.id(), a.role(), false, refusal));
            return;
        }
        if (st.incoming != null && st.incoming.envelopeId() == env.id() && st.incoming.from().equals(from)) {
            return;
        }
        st.incoming = new Incoming(from, back.get(), env.id(), a, ctx.clock().nowMillis());
        st.lastAssignmentFrom = from;
        st.lastAssignmentId = env.id();
        withdrawAnswers(from);
        discoverEarly(a);
        // The role's own files come right behind the assignment (Recruiter sends them unasked), then
        // those of the roles it manages (this cell sends them to its children): the role starts
        // when its own are in. Any still missing after a heartbeat period is asked for (expire).
        completeIfReady();
    }

    /**
     * A vehicle holding nothing that is taking a role which manages others broadcasts the role's
     * discovery now, while the role's files are on their way and loading, instead of once the role
     * has started: the answers come meanwhile. The role's own policies still decide on every
     * answer, once the role has started (Recruiter.takeUpEarlyReplies); what overlaps the download
     * is only the wait for the answers.
     */
    private void discoverEarly(RoleAssignment a) {
        if (!st.seats.isEmpty() || st.recruitingHeld || ctx.slots().managedRoles(a.role()).isEmpty()) {
            return;
        }
        st.earlyReplies.clear();
        long id = ctx.comm().broadcast(new Discovery(ctx.missionId(), a.role(), ctx.slots().level(a.role()), a.epoch()));
        st.earlyDiscoveryMillis = ctx.clock().nowMillis() + ctx.comm().backlogMillis();
        st.discoveries.sent(id, st.earlyDiscoveryMillis);
    }

    /** The policy files of {@code role} itself: its role-missions and authorisations. */
    private Set<String> ownPolicyUris(String role) {
        return ctx.ownPolicyUris(role);
    }

    /**
     * Asks the manager of the role being taken for those of the role's own files that have not
     * come: the versions the assignment names, the others in the version the manager holds.
     */
    private void askForOwnPolicies(Incoming in) {
        RoleAssignment a = in.assignment();
        Set<String> own = ownPolicyUris(a.role());
        Set<String> listed = new LinkedHashSet<>();
        for (PolicyRef ref : a.policies()) {
            listed.add(ref.uri());
            if (own.contains(ref.uri()) && !ctx.store().has(ref)) {
                ctx.comm().send(in.address(), new PolicyRequest(ref.uri(), ref.version()));
            }
        }
        for (String uri : own) {
            if (!listed.contains(uri) && ctx.store().get(uri, PolicyStore.ANY_VERSION).isEmpty()) {
                ctx.comm().send(in.address(), new PolicyRequest(uri, PolicyStore.ANY_VERSION));
            }
        }
    }

    /**
     * Fetches, from the manager that gave {@code a}, whatever the roles below the role taken need and
     * this cell does not hold, but the files {@code own} (coming, or held): the versions the
     * assignment names, and any other file of the subtree.
     */
    private void fetchSubtreePolicies(Address from, RoleAssignment a, Set<String> own) {
        Set<String> listed = new LinkedHashSet<>();
        for (PolicyRef ref : a.policies()) {
            listed.add(ref.uri());
            if (!own.contains(ref.uri()) && !ctx.store().has(ref)) {
                ctx.comm().send(from, new PolicyRequest(ref.uri(), ref.version()));
            }
        }
        for (String uri : ctx.subtreePolicyUris(a.role())) {
            if (!listed.contains(uri) && !own.contains(uri) && ctx.store().get(uri, PolicyStore.ANY_VERSION).isEmpty()) {
                ctx.comm().send(from, new PolicyRequest(uri, PolicyStore.ANY_VERSION));
            }
        }
    }

    /** Why this cell will not take a role from {@code from}, or null when it will. */
    private String refusal(String from, RoleAssignment a) {
        if (!a.mission().equals(ctx.missionId())) {
            return "assignment is for mission '" + a.mission() + "', this vehicle serves '" + ctx.missionId() + "'";
        }
        if (ctx.slots().mission().role(a.role()).isEmpty() || a.role().equals(Mission.COMMANDER)) {
            return "role '" + a.role() + "' cannot be assigned in mission '" + ctx.missionId() + "'";
        }
        if (st.acting) {
            return "this vehicle is the acting commander";
        }
        if (st.left) {
            return "this vehicle has left the team";
        }
        if (a.ancestors().contains(ctx.self())) {
            return "'" + from + "' descends from this vehicle; taking a role from it would close a cycle";
        }
        Long until = st.abandoned.get(from);
        if (until != null && ctx.clock().nowMillis() < until) {
            return "'" + from + "' may still name this vehicle as its parent";
        }
        if (st.parent != null && !st.parent.vehicle().equals(from) && !promotion(a.role(), a.epoch())) {
            return "this vehicle already has parent '" + st.parent.vehicle() + "'";
        }
        if (st.incoming != null && !st.incoming.from().equals(from)) {
            return "this vehicle is taking a role from '" + st.incoming.from() + "'";
        }
        if (st.incoming != null && !st.incoming.assignment().role().equals(a.role())) {
            return "this vehicle is still taking role '" + st.incoming.assignment().role() + "'; one role at a time";
        }
        if (!ctx.slots().role(a.role()).requirement().isMetBy(ctx.description())) {
            return "this vehicle lacks " + ctx.slots().role(a.role()).requirement().missingFrom(ctx.description()).describe();
        }
        return null;
    }

    private void completeIfReady() {
        Incoming in = st.incoming;
        if (in == null) {
            return;
        }
        Set<String> own = ownPolicyUris(in.assignment().role());
        if (!in.assignment().policies().stream().filter(ref -> own.contains(ref.uri())).allMatch(ctx.store()::has)
                || !ctx.policiesHeld(in.assignment().role())) {
            return;
        }
        st.incoming = null;
        RoleAssignment a = in.assignment();
        Seat seat = new Seat(a.role(), slotOf(a));
        if (st.acting || st.left) {
            // It took over as commander (or left) while the role's policies were on their way.
            String why = st.acting ? "this vehicle is now the acting commander" : "this vehicle has left the team";
            ctx.emit(CellEvent.Kind.REFUSED, seat + " from " + in.from() + ": " + why);
            ctx.comm().send(in.address(), new AssignmentResponse(in.envelopeId(), a.role(), false, why));
            return;
        }
        if (st.parent != null && !st.parent.vehicle().equals(in.from())) {
            if (!promotion(a.role(), a.epoch())) {
                ctx.emit(CellEvent.Kind.REFUSED, seat + " from " + in.from() + ": no longer free to move up");
                ctx.comm().send(in.address(), new AssignmentResponse(in.envelopeId(), a.role(), false, "no longer free"));
                return;
            }
            ctx.emit(CellEvent.Kind.RELEASED, "moves up from " + st.seats + " under " + st.parent.vehicle() + " to " + seat
                    + " under " + in.from());
            ctx.send(st.parent.address(), new Leave("'" + ctx.self() + "' moves up to " + seat + " under '" + in.from() + "'"));
            seating.dropEverything("moves up to " + seat);
        }
        boolean sameParent = st.parent != null && st.parent.vehicle().equals(in.from());
        List<Seat> before = sameParent ? List.copyOf(st.seats) : List.of();
        // What the parent says this vehicle keeps from it, then its own (hosted) seats that still fit
        // and that a seat it still holds owns: a seat hosted as the manager of a seat given up now
        // belongs to that seat's next holder, who hosts it or gives it.
        List<Seat> kept = before.stream().filter(s -> a.keeps().contains(s.toString())).toList();
        List<Seat> after = new ArrayList<>(ctx.slots().afterAssign(kept, seat));
        boolean grew = true;
        while (grew) {   // a hosted seat may own another hosted seat
            grew = false;
            for (Seat s : before) {
                if (!after.contains(s) && ownsItself(after, s) && ctx.canAlsoHold(after, s)) {
                    after.add(s);
                    grew = true;
                }
            }
        }
        if (before.stream().noneMatch(s -> s.role().equals(seat.role()))) {
            try {
                ctx.host().loadRole(seat.role(), ctx.store());
            } catch (RoleLoadException e) {
                String why = "loading role '" + seat.role() + "' failed: " + e.getMessage();
                ctx.emit(CellEvent.Kind.REFUSED, seat + " from " + in.from() + ": " + why);
                ctx.comm().send(in.address(), new AssignmentResponse(in.envelopeId(), a.role(), false, TeamContext.truncate(why)));
                return;
            }
        }
        Set<String> keptRoles = new LinkedHashSet<>();
        after.forEach(s -> keptRoles.add(s.role()));
        for (Seat s : before) {
            if (!after.contains(s)) {
                if (!keptRoles.contains(s.role())) {
                    ctx.host().withdrawRole(s.role());
                }
                ctx.emit(CellEvent.Kind.RELEASED, s + ": gives way to " + seat);
            }
        }
        st.seats.clear();
        st.seats.addAll(after);
        st.parent = new Parent(in.from(), in.address());
        // What the assignment says replaces what the parent's statuses said: hold none of its versions.
        st.statusVersionFrom = null;
        st.ancestors = TeamContext.lineage(in.from(), a.ancestors());
        st.epoch = a.epoch();
        st.lastStatusMillis = ctx.clock().nowMillis();
        // The answer leaves now; the parent hears it later, so its failure timeout starts later still.
        st.leaseUntilMillis = ctx.clock().nowMillis() + ctx.timing().leaseMillis();
        st.linksChanged();
        st.lapseNoted = false;
        if (!ctx.slots().role(seat.role()).isSecondary() || st.identity == null) {
            st.identity = a.identity();
        }
        seating.recomputeOwnership();
        ctx.emit(CellEvent.Kind.ACCEPTED, seat + " " + a.identity() + " from " + in.from() + ", holds " + st.seats);
        ctx.comm().send(in.address(), new AssignmentResponse(in.envelopeId(), a.role(), true, ""));
        if (!ctx.slots().managedRoles(a.role()).isEmpty()) {
            // The files of the roles further down the manager does not send: ask for them now.
            fetchSubtreePolicies(in.address(), a, ctx.policiesWithAssignment(a.role()));
            subtreeFetch = new SubtreeFetch(in.from(), in.address(), a, ctx.clock().nowMillis());
        }
        if (!a.handover().isEmpty()) {
            st.handedOver = a.handover();
            ctx.host().importTaskStates(a.role(), a.handover());
            ctx.host().raise("handover", "handover", a.role(), a.handover());
        }
        roleTaken.run();
    }

    /**
     * Whether this vehicle is able to hold one of the roles a manager of {@code managerRole} manages:
     * the cheap check before answering its discovery. A manager gives only seats it owns, all of
     * roles it manages, and only to a vehicle whose full description meets the seat's role
     * requirement (Algorithm 2), so a vehicle that meets none of them could never be given a seat by
     * it; its answer would only cost the manager a first contact to verify and a {@code newUAV} to
     * decide. Every cell knows the mission, so this needs nothing on the wire.
     */
    private boolean couldHoldAny(String managerRole) {
        // The mission and this vehicle's description are fixed for the cell's life: asked once per role.
        return couldHold.computeIfAbsent(managerRole, m -> {
            if (ctx.slots().mission().role(m).isEmpty() && !m.equals(Mission.COMMANDER)) {
                return false;
            }
            return ctx.slots().managedRoles(m).stream()
                    .anyMatch(r -> ctx.slots().role(r).requirement().isMetBy(ctx.description()));
        });
    }

    /**
     * Whether this vehicle, attached to its team, would move up to {@code role}: a role before its
     * own primary role in the mission's order (the surveyor before the detector), offered within its
     * own team, that it is able to hold. A team short of a surveyor then takes one from among its
     * detectors, as the reasonably-optimal configuration would.
     */
    private boolean promotion(String role, long offeredEpoch) {
        if (st.parent == null || st.suspended() || st.seats.isEmpty() || st.acting || offeredEpoch != st.epoch
                || ctx.slots().mission().role(role).isEmpty() || role.equals(Mission.COMMANDER)) {
            return false;
        }
        String mine = st.seats.get(0).role();
        return ctx.slots().rank(role) < ctx.slots().rank(mine) && ctx.slots().role(role).requirement().isMetBy(ctx.description());
    }

    /**
     * Whether {@link #promotion} holds for one of the roles a manager of {@code managerRole} manages:
     * the same answer, from the best rank among them this vehicle is able to hold, asked of the
     * mission once per manager's role.
     */
    private boolean promotable(String managerRole, long offeredEpoch) {
        if (st.parent == null || st.suspended() || st.seats.isEmpty() || st.acting || offeredEpoch != st.epoch) {
            return false;
        }
        int best = bestHoldableRank.computeIfAbsent(managerRole, m -> {
            int r = Integer.MAX_VALUE;
            for (String role : ctx.slots().managedRoles(m)) {
                if (ctx.slots().mission().role(role).isPresent() && !role.equals(Mission.COMMANDER)
                        && ctx.slots().role(role).requirement().isMetBy(ctx.description())) {
                    r = Math.min(r, ctx.slots().rank(role));
                }
            }
            return r;
        });
        return best < ctx.slots().rank(st.seats.get(0).role());
    }

    /** Whether {@code seat} is owned by another of {@code held}: a secondary seat this vehicle hosts itself. */
    private boolean ownsItself(List<Seat> held, Seat seat) {
        return ctx.slots().owner(seat).map(held::contains).orElse(false);
    }

    private int slotOf(RoleAssignment a) {
        for (int s = 0; s < ctx.slots().optimal(a.role()); s++) {
            if (ctx.slots().sequence(new Seat(a.role(), s)) == a.identity().sequence()) {
                return s;
            }
        }
        return 0;
    }

    void onPolicyReply(Envelope env, PolicyReply r) {
        if (!ctx.store().accept(r.uri(), r.version(), r.text())) {
            ctx.reject(env, "policy " + r.uri() + " arrived with version " + r.version() + " but its text has version "
                    + PolicyStore.versionOf(r.text()));
            return;
        }
        completeIfReady();
    }

    void onInvocation(Envelope env, Invocation i) {
        if (!i.operation().equals("release") || st.parent == null || !st.parent.vehicle().equals(env.sender())) {
            ctx.reject(env, "invocation '" + i.operation() + "' on role '" + i.role() + "' is not accepted from "
                    + env.sender());
            return;
        }
        st.seats.stream().filter(s -> s.role().equals(i.role())).findFirst()
                .ifPresent(s -> seating.dropOwnSeat(s, "released by its parent"));
    }

    /**
     * Asks for the role's own files that have not come a heartbeat period after the assignment, and
     * for the files of the roles below it that have not come a heartbeat period after it started
     * (the manager's were lost for good, or it could not send them); refuses the role being taken
     * when its policies did not arrive in time.
     */
    void expire(long now) {
        if (subtreeFetch != null && now - subtreeFetch.sinceMillis() >= ctx.timing().comTimeoutMillis()) {
            SubtreeFetch due = subtreeFetch;
            subtreeFetch = null;
            if (st.parent != null && st.parent.vehicle().equals(due.manager())
                    && st.seats.stream().anyMatch(s -> s.role().equals(due.assignment().role()))) {
                fetchSubtreePolicies(due.from(), due.assignment(), ownPolicyUris(due.assignment().role()));
            }
        }
        if (st.incoming != null && st.incoming != askedForOwnPolicies
                && now - st.incoming.sinceMillis() >= ctx.timing().comTimeoutMillis()) {
            askedForOwnPolicies = st.incoming;
            askForOwnPolicies(st.incoming);
        }
        if (st.incoming != null && now - st.incoming.sinceMillis() > ctx.timing().failureTimeoutMillis()) {
            Incoming in = st.incoming;
            st.incoming = null;
            ctx.emit(CellEvent.Kind.REFUSED, in.assignment().role() + " from " + in.from() + ": its policies did not arrive");
            ctx.send(in.address(), new AssignmentResponse(in.envelopeId(), in.assignment().role(), false,
                    "policies did not arrive in time"));
        }
    }
}
