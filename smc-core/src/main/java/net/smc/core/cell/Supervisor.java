package net.smc.core.cell;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.function.Predicate;

import net.smc.core.capability.CapabilitySummary;
import net.smc.core.cell.TeamState.Child;
import net.smc.core.cell.TeamState.Heard;
import net.smc.core.cell.TeamState.Owned;
import net.smc.core.cell.TeamState.PendingCapability;
import net.smc.core.cell.TeamState.StatusContent;
import net.smc.core.message.CapabilityRequest;
import net.smc.core.message.Echo;
import net.smc.core.message.Envelope;
import net.smc.core.message.Heartbeat;
import net.smc.core.message.Leave;
import net.smc.core.message.PolicyRequest;
import net.smc.core.message.Status;
import net.smc.core.mission.MissionRole;
import net.smc.core.role.RoleLoadException;
import net.smc.core.transport.Address;
import net.smc.core.transport.Cancellable;

/**
 * The manager's tick and its children's heartbeats: answers each heartbeat with a status, or a
 * bare echo while the child holds the current status (either
 * renews the child's lease; a child whose heartbeat went unanswered for a period and a half gets
 * one from the tick), detects silent children and raises {@code UAVFailure} (Table II),
 * carries out re-assignment, and moves the team towards the reasonably-optimal configuration
 * (secondary seats hosted, children promoted or swapped). Owns HEARTBEAT.
 */
final class Supervisor {
    /**
     * A child is sent a status of this cell's own only when none went to it (in answer to its
     * heartbeats) for this many half heartbeat periods: in the steady state the answer to each
     * heartbeat is the only status, one per period; when a heartbeat is lost, the tick sends one.
     * One and a half periods, so that the jitter of heartbeats does not bring a second status.
     */
    private static final int STATUS_GAP_HALF_PERIODS = 3;
    /** When {@link #rediscover} last discovered (far in the past: never). */
    private long rediscoveredMillis = Long.MIN_VALUE / 2;
    /** A rediscovery held back by the rate limit, scheduled for when the limit allows it, or null. */
    private Cancellable rediscoveryDue;
    /** Whether the cell stopped: what fails as its communication stops asks for no rediscovery. */
    private boolean stopped;
    /** The early repeats of discovery while a seat stays open. */
    private final DiscoveryRepeats repeats;

    private final TeamContext ctx;
    private final TeamState st;
    private final Seating seating;
    private final TeamCounts counts;
    private final BackupCommander backup;
    private final Recruiter recruiter;
    private final Merge merge;

    Supervisor(TeamContext ctx, TeamState st, Seating seating, TeamCounts counts, BackupCommander backup, Recruiter recruiter, Merge merge) {
        this.ctx = ctx;
        this.st = st;
        this.seating = seating;
        this.counts = counts;
        this.backup = backup;
        this.recruiter = recruiter;
        this.merge = merge;
        this.repeats = new DiscoveryRepeats(ctx, () -> !stopped && !st.seats.isEmpty() && st.hasVacancy() && !st.recruitingHeld,
                this::rediscover);
    }

    void onHeartbeat(Envelope env, Heartbeat h) {
        Child child = st.children.get(env.sender());
        Optional<Address> back = ctx.address(env.sender());
        if (back.isEmpty()) {
            return;
        }
        // The heartbeat names the child's primary seat: it must be one this cell gave it.
        Seat primary = new Seat(h.role(), h.state());
        if (child == null || !child.seats.contains(primary)) {
            Optional<Seat> reserved = st.owned.containsKey(primary) && env.sender().equals(st.owned.get(primary).pendingFor)
                    ? Optional.of(primary) : Optional.empty();
            if (reserved.isEmpty()) {
                if (child != null) {
                    st.children.remove(env.sender());
                    st.linksChanged();
                    seating.vacate(child);
                    ctx.emit(CellEvent.Kind.REJECTED, env.sender() + " reports role " + h.role() + " but holds " + child.seats
                            + " from this cell; let go");
                }
                ctx.send(back.get(), new Leave("'" + env.sender() + "' is not a child of '" + ctx.self() + "' as " + h.role()));
                return;
            }
            recruiter.accepted(env.sender(), reserved.get()); // its answer was lost; its heartbeat says it took the seat
            child = st.children.get(env.sender());
            child.confirmedBy.put(reserved.get(), env.id());
        }
        child.lastHeard = ctx.clock().nowMillis();
        child.address = back.get();
        if (env.id() >= child.lastHeartbeat) {
            child.lastHeartbeat = env.id();
            child.statusVersionHeld = h.statusVersion();
        }
        sendStatus(child);
    }

    /**
     * Tells a child the team's state, echoing its latest heartbeat heard (which renews its lease):
     * a bare {@link Echo} when that heartbeat said the child holds the current version of this
     * cell's status, else the whole status with its version (so a status that was lost is sent
     * again until a heartbeat names it).
     */
    private void sendStatus(Child child) {
        if (child.address != null && st.identity != null) {
            child.statusSentMillis = ctx.clock().nowMillis();
            long echo = child.consistent ? child.lastHeartbeat : 0;
            long version = statusVersion();
            if (child.statusVersionHeld == version) {
                ctx.send(child.address, new Echo(echo == 0 ? 0 : Echo.tagOf(echo)));
            } else {
                StatusContent c = st.statusContent;
                ctx.send(child.address, new Status(ctx.missionId(), c.identity(), c.commander(), c.epoch(), c.teamSize(), echo,
                        c.ancestors(), version));
            }
        }
    }

    /** The version of this cell's status as it is now: grows whenever its content changes. */
    private long statusVersion() {
        StatusContent now = new StatusContent(st.identity, st.commander == null ? ctx.self() : st.commander, st.epoch,
                counts.teamSize(), st.ancestors);
        if (!now.equals(st.statusContent)) {
            st.statusContent = now;
            st.statusVersion++;
        }
        return st.statusVersion;
    }

    void asManager(long now) {
        // A child left holding nothing from this cell (its seats taken back, or reconciled away),
        // with no assignment in flight to it, is no child: drop it, so that it can be recruited again
        // (discovery replies from children are ignored) instead of lingering, neither supervised nor free.
        if (st.children.values().removeIf(c -> c.seats.isEmpty()
                && st.owned.values().stream().noneMatch(o -> c.vehicle.equals(o.pendingFor)))) {
            st.linksChanged();
        }
        List<Child> silent = st.children.values().stream()
                .filter(c -> !c.seats.isEmpty() && now - c.lastHeard > ctx.timing().failureTimeoutMillis())
                // An assignment in flight may still make it keep its seats: wait for its answer or expiry.
                .filter(c -> st.owned.values().stream().noneMatch(o -> c.vehicle.equals(o.pendingFor))).toList();
        silent.forEach(c -> st.children.remove(c.vehicle));
        if (!silent.isEmpty()) {
            st.linksChanged();
        }
        for (Child child : silent) {
            failed(child, now - child.lastHeard);
        }
        for (Child c : st.children.values()) {
            if (!c.seats.isEmpty()) {
                if (now - c.statusSentMillis >= STATUS_GAP_HALF_PERIODS * ctx.timing().comTimeoutMillis() / 2) {
                    sendStatus(c); // its heartbeat went unanswered (lost, say): a status of this cell's own
                }
                if (c.description == null && !st.capabilityRequests.containsKey(c.vehicle) && c.address != null) {
                    // A child known from a roster: learn what it can do, to move it if need be.
                    st.capabilityRequests.put(c.vehicle, new PendingCapability(now));
                    ctx.comm().send(c.address, new CapabilityRequest(c.seats.get(0).role()),
                            TeamContext.failureOnly(() -> st.capabilityRequests.remove(c.vehicle)));
                }
            }
        }
        fillSecondarySeats();
        swapTowardsOptimal(now);
        boolean open = noteDiscovering(now + ctx.comm().backlogMillis());
        if (open || (st.acting && !st.recruitingHeld && st.ticks % Timing.BEACON_TICKS == 0)) {
            merge.discover();
        }
        if (st.acting && (st.ticks % Timing.ROSTER_TICKS == 0 || backup.rosterDue())) {
            backup.sendRoster();
        }
        counts.updateMissionState();
    }

    /**
     * Whether this cell has an open seat; a DISCOVERING event marks each start of discovery, whose
     * repeats follow the discovery that leaves at {@code discoveryLeftMillis}.
     */
    private boolean noteDiscovering(long discoveryLeftMillis) {
        // While a policy holds recruiting, the manager looks for no one: no discovery, so no assignment.
        boolean open = st.hasVacancy() && !st.recruitingHeld;
        if (open && !st.discovering) {
            ctx.emit(CellEvent.Kind.DISCOVERING, "discovers for "
                    + st.owned.keySet().stream().filter(st::open).map(Seat::toString).toList());
            repeats.start(discoveryLeftMillis);
        }
        st.discovering = open;
        return open;
    }

    /** A discovery reply gave a round trip: a first repeat due later than the estimate now says is brought forward. */
    void roundTripMeasured() {
        repeats.roundTripMeasured();
    }

    /**
     * Discovers at once when this cell has an open seat: a manager whose role has just started (or
     * a commander starting) looks for its children now rather than at its next tick, so a tree of
     * depth d forms without waiting up to d heartbeat periods. The tick goes on discovering every
     * period while a seat stays open. Returns whether it discovered.
     */
    boolean discoverNow() {
        if (!st.seats.isEmpty() && !st.owned.isEmpty() && noteDiscovering(ctx.clock().nowMillis() + ctx.comm().backlogMillis())) {
            merge.discover();
            return true;
        }
        return false;
    }

    /**
     * This cell has just taken a role. When the discovery it sent as the assignment arrived
     * (Assignee) left less than the cell's retransmission timeout ago, the answers may still be
     * coming: its discovery starts (a DISCOVERING event, and its early repeats, timed from that
     * discovery) without a second broadcast.
     */
    void roleStarted() {
        long sinceEarly = ctx.clock().nowMillis() - st.earlyDiscoveryMillis;
        if (sinceEarly < ctx.comm().sender().cellTimeoutMillis()) {
            if (!st.seats.isEmpty() && !st.owned.isEmpty()) {
                noteDiscovering(st.earlyDiscoveryMillis);
            }
            return;
        }
        discoverNow();
    }

    /**
     * A seat offered to a vehicle is open again (it refused, or never answered): discovers at once,
     * unless capability requests are still out (their answers will find the seat open, with no
     * broadcast: in a large team many managers compete for the same free vehicles, and each
     * rediscovery would bring every one of them to answer again), and not within a quarter
     * heartbeat period of the last such discovery, so that vehicles refusing every offer cost at
     * most four extra discoveries a period: one asked for sooner runs when that quarter period has
     * passed. Only a discovery sent counts: a call that found no seat open (another vehicle is
     * being given it) does not hold back the next.
     */
    void rediscover() {
        if (stopped || !st.capabilityRequests.isEmpty() || rediscoveryDue != null) {
            return; // the decline or failure of the last request out asks again; a due one will run
        }
        long now = ctx.clock().nowMillis();
        long allowedAt = rediscoveredMillis + ctx.timing().comTimeoutMillis() / 4;
        if (now >= allowedAt) {
            if (discoverNow()) {
                rediscoveredMillis = now; // only a discovery sent counts against the limit
            }
            return;
        }
        // Held back by the rate limit: discovers when the limit allows, not a period later at the tick.
        rediscoveryDue = ctx.scheduler().schedule(allowedAt - now, () -> {
            rediscoveryDue = null;
            rediscover();
        });
    }

    /** The cell stops (crashes, or is shut down): a rediscovery scheduled is called off. */
    void stop() {
        stopped = true;
        if (rediscoveryDue != null) {
            rediscoveryDue.cancel();
            rediscoveryDue = null;
        }
        repeats.stop();
    }

    /** A child was silent for the failure timeout: vacate its seats and raise UAVFailure for each. */
    private void failed(Child child, long silentMillis) {
        List<Seat> lost = child.seats;
        seating.vacate(child);
        for (Seat s : lost) {
            st.handover.put(s.role(), child.state);
        }
        ctx.emit(CellEvent.Kind.FAILURE, child.vehicle + " silent for " + silentMillis + " ms; held " + lost
                + ", last state " + child.state);
        for (Seat s : lost) {
            // Table II decides: UAVFailure(name role uav state).
            ctx.host().raise("UAVFailure", "UAVFailure", s.role(), child.vehicle, child.state);
        }
        backup.rosterChanged();
        counts.updateMissionState();
    }

    /**
     * Asked by a policy ({@code root/role/<manager> reassign: role scheme: s}): find the role a new
     * holder. A free capable vehicle first; else a child moved from a role of lower priority; else
     * the team contracts (the seat stays vacant, a secondary one returns to its primary's vehicle).
     */
    void reassign(String managingRole, String role, String scheme) {
        Optional<Seat> seat = st.owned.keySet().stream().filter(s -> s.role().equals(role) && st.open(s)
                && st.owned.get(s).holder == null).min(ctx.slots()::compare);
        if (seat.isEmpty()) {
            ctx.emit(CellEvent.Kind.REASSIGNING, role + " (scheme " + scheme + "): no vacant seat");
            return;
        }
        MissionRole wanted = ctx.slots().role(role);
        long now = ctx.clock().nowMillis();
        Optional<String> free = freeFor(wanted, now);
        if (free.isEmpty() && recruiter.checkUntil(ctx.timing().failureTimeoutMillis(), couldTake(wanted))) {
            free = freeFor(wanted, now); // replies held unchecked, checked now: only checked ones are chosen from
        }
        if (free.isPresent()) {
            ctx.emit(CellEvent.Kind.REASSIGNING, seat.get() + " (scheme " + scheme + ") to free vehicle " + free.get());
            recruiter.requestFullCapability(free.get(), role);
            return;
        }
        Optional<Child> movable = st.children.values().stream()
                .filter(c -> !c.seats.isEmpty() && c.description != null && wanted.requirement().isMetBy(c.description))
                .filter(c -> c.seats.stream().allMatch(s -> !s.role().equals(role) && ctx.slots().compare(s, seat.get()) > 0))
                .filter(c -> st.owned.values().stream().noneMatch(o -> c.vehicle.equals(o.pendingFor)))
                .max(Comparator.comparing((Child c) -> c.seats.get(0), ctx.slots()::compare));
        if (movable.isPresent()) {
            Child c = movable.get();
            ctx.emit(CellEvent.Kind.REASSIGNING, seat.get() + " (scheme " + scheme + ") moves " + c.vehicle + " from "
                    + c.seats);
            recruiter.assign(c.vehicle, c.description, seat.get());
            return;
        }
        ctx.emit(CellEvent.Kind.REASSIGNING, seat.get() + " (scheme " + scheme + "): no vehicle free; the team contracts");
        fillSecondarySeats();
    }

    /** Vacant seats of secondary roles go to the vehicle holding their primary seat, if it may take them. */
    private void fillSecondarySeats() {
        for (Map.Entry<Seat, Owned> e : st.owned.entrySet()) {
            Seat seat = e.getKey();
            Owned o = e.getValue();
            if (o.holder != null || o.pendingFor != null) {
                continue;
            }
            Optional<Seat> hostSeat = ctx.slots().host(seat);
            if (hostSeat.isEmpty()) {
                continue;
            }
            if (st.seats.contains(hostSeat.get()) && !st.suspended()) {
                hostLocally(seat, o);
                continue;
            }
            // The seat's own host, else (when this cell owns the primary's seats too, as the
            // centralised commander does) any holder of the primary role that may take it.
            List<Seat> hosts = new ArrayList<>(List.of(hostSeat.get()));
            st.owned.keySet().stream().filter(h -> h.role().equals(hostSeat.get().role()) && !h.equals(hostSeat.get()))
                    .forEach(hosts::add);
            for (Seat h : hosts) {
                Owned ho = st.owned.get(h);
                Child c = ho == null || ho.holder == null ? null : st.children.get(ho.holder);
                if (c != null && c.description != null && ctx.canAlsoHold(c.seats, seat)
                        && st.owned.values().stream().noneMatch(x -> c.vehicle.equals(x.pendingFor))
                        && ctx.slots().role(seat.role()).requirement().isMetBy(c.description)) {
                    recruiter.assign(c.vehicle, c.description, seat);
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
        MissionRole wanted = ctx.slots().role(open.role());
        Optional<Child> movable = st.children.values().stream()
                .filter(c -> !c.seats.isEmpty() && c.description != null && wanted.requirement().isMetBy(c.description))
                .filter(c -> c.seats.stream().allMatch(s -> ctx.slots().rank(s.role()) > ctx.slots().rank(open.role())))
                .filter(c -> st.owned.values().stream().noneMatch(o -> c.vehicle.equals(o.pendingFor)))
                .max(Comparator.comparing((Child c) -> c.seats.get(0), ctx.slots()::compare));
        if (movable.isEmpty()) {
            return false;
        }
        ctx.emit(CellEvent.Kind.REASSIGNING, open + ": moves " + movable.get().vehicle + " up from " + movable.get().seats);
        recruiter.assign(movable.get().vehicle, movable.get().description, open);
        return true;
    }

    /** Whether a vehicle heard of can take a seat of {@code wanted}: able to, and free to ({@link TeamState#couldTake}). */
    private Predicate<Heard> couldTake(MissionRole wanted) {
        return h -> TeamState.couldTake(h, wanted.name(), ctx.slots()) && wanted.requirement().isMetBy(h.summary());
    }

    /**
     * The first by name of the vehicles heard lately (checked replies) that can take {@code wanted}:
     * free, or holding a role ranked after it elsewhere ({@link TeamState#couldTake}).
     */
    private Optional<String> freeFor(MissionRole wanted, long now) {
        Predicate<Heard> takes = couldTake(wanted);
        return st.heard.entrySet().stream()
                .filter(e -> now - e.getValue().atMillis() <= ctx.timing().failureTimeoutMillis())
                .filter(e -> !st.children.containsKey(e.getKey()) && !st.capabilityRequests.containsKey(e.getKey()))
                .filter(e -> takes.test(e.getValue()))
                .map(Map.Entry::getKey).sorted().findFirst();
    }

    /**
     * A local improvement towards the reasonably-optimal configuration: an open seat (vacant, or
     * hosted) that no free vehicle heard of can take goes to a child holding a seat of another role
     * that a free vehicle can take; that seat is then refilled through discovery. So a surveyor-like
     * vehicle detecting hazards becomes the relay, and the free detector the detector.
     */
    private void swapTowardsOptimal(long now) {
        for (Seat open : st.owned.keySet().stream().filter(st::open).sorted(ctx.slots()::compare).toList()) {
            MissionRole wanted = ctx.slots().role(open.role());
            if (freeFor(wanted, now).isPresent()
                    || recruiter.checkUntil(ctx.timing().failureTimeoutMillis(), couldTake(wanted))) {
                continue; // discovery will fill it directly
            }
            List<CapabilitySummary> free = st.heard.entrySet().stream()
                    .filter(e -> now - e.getValue().atMillis() <= ctx.timing().failureTimeoutMillis())
                    .filter(e -> !st.children.containsKey(e.getKey()) && !st.capabilityRequests.containsKey(e.getKey()))
                    .filter(e -> e.getValue().free())
                    .map(e -> e.getValue().summary()).toList();
            if (st.owned.get(open).holder == null && promoteChild(open)) {
                return;
            }
            if (free.isEmpty()) {
                continue; // nobody to swap with
            }
            for (Child c : st.children.values()) {
                if (c.seats.size() != 1 || c.description == null || !wanted.requirement().isMetBy(c.description)
                        || st.owned.values().stream().anyMatch(x -> c.vehicle.equals(x.pendingFor))) {
                    continue;
                }
                Seat held = c.seats.get(0);
                if (held.role().equals(open.role()) || ctx.canAlsoHold(List.of(held), open)
                        || ctx.slots().compare(held, open) < 0 && !ctx.slots().minimal(open)) {
                    continue;
                }
                MissionRole current = ctx.slots().role(held.role());
                if (free.stream().anyMatch(f -> current.requirement().isMetBy(f))) {
                    ctx.emit(CellEvent.Kind.REASSIGNING, open + ": moves " + c.vehicle + " from " + held
                            + ", which a free vehicle can take");
                    recruiter.giveSeat(c.vehicle, c.description, open);
                    return;
                }
            }
        }
    }

    private void hostLocally(Seat seat, Owned o) {
        if (!ctx.canAlsoHold(st.seats, seat) || !ctx.slots().role(seat.role()).requirement().isMetBy(ctx.description())) {
            return;
        }
        if (!ctx.policiesHeld(seat.role())) {
            requestMissingPolicies(seat.role());
            return;
        }
        try {
            ctx.host().loadRole(seat.role(), ctx.store());
        } catch (RoleLoadException ex) {
            ctx.emit(CellEvent.Kind.REJECTED, "cannot host " + seat + ": " + ex.getMessage());
            return;
        }
        st.seats.add(seat);
        st.linksChanged();
        o.holder = ctx.self();
        seating.recomputeOwnership();
        ctx.emit(CellEvent.Kind.HOSTING, seat + " beside " + st.seats.get(0));
        counts.updateMissionState();
    }

    /** Asks the parent (or, for a repository holder, the local repository) for a role's missing files. */
    private void requestMissingPolicies(String role) {
        for (String uri : ctx.subtreePolicyUris(role)) {
            if (ctx.store().get(uri, PolicyStore.ANY_VERSION).isPresent()) {
                continue;
            }
            if ((st.acting || st.backupRank >= 0) && ctx.fromRepository(uri).isPresent()) {
                continue;
            }
            if (st.parent != null) {
                ctx.send(st.parent.address(), new PolicyRequest(uri, PolicyStore.ANY_VERSION));
            }
        }
    }
}
