package net.smc.core.cell;

import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.function.Predicate;
import java.util.stream.Stream;

import net.smc.core.capability.CapabilitySummary;
import net.smc.core.cell.TeamState.Heard;
import net.smc.core.cell.TeamState.Unchecked;
import net.smc.core.message.DiscoveryReply;
import net.smc.core.transport.Address;
import net.smc.core.transport.Cancellable;

/**
 * The discovery replies a manager's policies decide on together, in the manager's order among its
 * siblings ({@link SiblingOrder}) rather than in the order they came: the replies of one burst (those
 * queued for the cell as the first of them was taken up), those that came while the manager's own
 * role was loading, and those heard lately when a seat opens again. Siblings hear the same vehicles
 * answer in much the same order; decided on one by one as they came, each sibling gave its seat to
 * the quickest, which took one and refused the others. Part of {@link Recruiter}.
 */
final class ReplyBatches {
    /** Table I and Algorithm 2 on one vehicle that answered with {@code summary} ({@link Recruiter}). */
    interface Decision {
        void decide(String vehicle, CapabilitySummary summary, long nowMillis);
    }

    private final TeamContext ctx;
    private final TeamState st;
    private final Decision decision;
    /** Told when a checked reply gave the sender a round trip (Supervisor re-times its discovery repeat). */
    private final Runnable measured;
    /** Discovers at once, whatever the rate limit of rediscoveries: when the own share's time ends (Supervisor). */
    private final Runnable discoverAfresh;
    /** The task that ends this manager's time of taking its own share only ({@link #takeUpEarly}), or null. */
    private Cancellable sharesEnd;
    /** The vehicle whose held discovery reply is being checked now ({@link #check}), or null. */
    private String checking;
    /** The vehicles whose replies came in the burst being taken up; decided on after it. */
    private final Set<String> burst = new LinkedHashSet<>();
    /** The task that decides on {@link #burst}, or null when none is due. */
    private Cancellable burstDue;

    ReplyBatches(TeamContext ctx, TeamState st, Decision decision, Runnable measured, Runnable discoverAfresh) {
        this.measured = measured;
        this.ctx = ctx;
        this.st = st;
        this.decision = decision;
        this.discoverAfresh = discoverAfresh;
    }

    /**
     * A discovery reply the transport holds unchecked ({@code AuthenticatingTransport.holdUnverified}),
     * from a vehicle that claims to be {@code claimed}: remembered as a vehicle to check, and put
     * with the others of its burst (or, while this cell's role is loading, with the early replies).
     * A reply naming none of this cell's latest discoveries, and a copy of the answer already held,
     * are not held. Nothing in it is acted on: when the batch is decided on, the replies are checked in this
     * manager's order among its siblings, one at a time while a seat is open, and each reply that
     * passes is decided on as any discovery reply ({@link #check}). So a manager that hears a hundred
     * vehicles and seats ten makes about ten first contacts, not a hundred; a forged reply costs one
     * check and is never decided on.
     */
    void addUnchecked(String claimed, Address from, DiscoveryReply r) {
        if ((st.owned.isEmpty() && st.incoming == null) || !r.mission().equals(ctx.missionId())
                || !r.summary().vehicle().equals(claimed) || !st.discoveries.answersOurs(r.inReplyTo())) {
            return;
        }
        Unchecked before = st.unchecked.get(claimed);
        if (before != null && before.inReplyTo() == r.inReplyTo() && before.from().equals(from)) {
            return; // a copy of the answer held (a network duplicate, a replay): no newer answer
        }
        st.unchecked.put(claimed, new Unchecked(from, ctx.clock().nowMillis(), r.inReplyTo()));
        if (st.owned.isEmpty()) {
            st.earlyReplies.add(claimed);
            return;
        }
        add(claimed);
    }

    /** Whether {@code vehicle}'s held reply is being checked now: the check's caller decides on it. */
    boolean isChecking(String vehicle) {
        return vehicle.equals(checking);
    }

    /**
     * Checks the reply held from {@code vehicle}, if one is: when it passes, it is in {@code st.heard}
     * (and not decided on by the receiving code), and the time from the discovery it answers to its
     * arrival is a round trip to the vehicle ({@link DiscoveryTimes}). Whether {@code vehicle}'s reply
     * is now checked and heard.
     */
    private boolean check(String vehicle) {
        Unchecked u = st.unchecked.remove(vehicle);
        if (u == null) {
            return st.heard.containsKey(vehicle);
        }
        checking = vehicle;
        try {
            ctx.host().checkHeld(u.from());
        } finally {
            checking = null;
        }
        Heard heard = st.heard.get(vehicle);
        boolean passed = heard != null && heard.atMillis() >= u.atMillis();
        if (passed && st.discoveries.measure(ctx.comm(), u.from(), u.inReplyTo(), u.atMillis())) {
            measured.run();
        }
        return passed;
    }

    /**
     * Checks the replies held from vehicles that answered within {@code windowMillis}, in the order
     * of their names, until one passes that {@code wanted} accepts: for a choice that reads the free
     * vehicles heard of (Supervisor's reassignment and swaps), which must see checked replies only.
     * Whether one was found.
     */
    boolean checkUntil(long windowMillis, Predicate<Heard> wanted) {
        long now = ctx.clock().nowMillis();
        for (String vehicle : st.unchecked.entrySet().stream().filter(e -> now - e.getValue().atMillis() <= windowMillis)
                .map(Map.Entry::getKey).sorted().toList()) {
            if (check(vehicle) && !st.children.containsKey(vehicle) && wanted.test(st.heard.get(vehicle))) {
                return true;
            }
        }
        return false;
    }

    /**
     * {@code vehicle}'s reply came: it is decided on, with the others of its burst, by a task that
     * runs after the datagrams already queued for the cell (delay 0), so a burst costs no wait.
     */
    void add(String vehicle) {
        burst.add(vehicle);
        if (burstDue == null) {
            burstDue = ctx.scheduler().schedule(0, this::decideOnBurst);
        }
    }

    private void decideOnBurst() {
        burstDue = null;
        List<String> vehicles = List.copyOf(burst);
        burst.clear();
        decideOn(vehicles, ctx.clock().nowMillis());
    }

    /**
     * The role this cell was taking has started: its policies decide on the vehicles that answered
     * the discovery it sent when the assignment arrived (Assignee), as on any discovery reply; on
     * those that answered within a heartbeat period, as an older answer may no longer hold (the
     * vehicle has taken a role since), and a fresh discovery costs less than an assignment refused.
     */
    void takeUpEarly() {
        long now = ctx.clock().nowMillis();
        beginOwnShare(now);
        List<String> early = st.earlyReplies.stream()
                .filter(v -> now - answeredMillis(v, now) <= ctx.timing().comTimeoutMillis()).toList();
        st.earlyReplies.clear();
        decideOn(early, now);
    }

    /**
     * The role has started: if it has siblings (managers of the same role, {@link SiblingOrder}) and
     * more than one open seat of a role ({@link #severalOfOneRole}), for
     * {@link Timing#ownShareMillis} it takes only the free vehicles of its own share of the ring,
     * which no sibling begins with, and leaves the others' shares to their owners; then, if a seat is
     * still open, it discovers afresh. A vehicle of another's share is decided on only once it has
     * answered after that time ({@link #decideOn}): its owner has had its time, and a vehicle taking
     * a role answers no discovery, so such an answer is from a vehicle its owner left. Siblings used
     * to decide on the answers as they came (a manager's own work on one answer keeps the next
     * waiting, so a burst was mostly one answer): each took the quickest vehicles from every share,
     * often a vehicle its owner was giving a seat to already (the assignment on the way behind other
     * files on the owner's radio, or the role's files still coming), which refused. The policies
     * still decide on every vehicle; only when they are asked changes.
     */
    private void beginOwnShare(long now) {
        if (sharesEnd != null) {
            sharesEnd.cancel();
            sharesEnd = null;
        }
        int siblings = st.owned.keySet().stream()
                .mapToInt(s -> ctx.slots().owner(s).map(m -> ctx.slots().optimal(m.role())).orElse(1)).max().orElse(1);
        long span = ctx.timing().ownShareMillis(siblings);
        if (span <= 0 || !severalOfOneRole()) {
            st.ownShareUntilMillis = Long.MIN_VALUE / 2;
            return;
        }
        st.ownShareUntilMillis = now + span;
        sharesEnd = ctx.scheduler().schedule(span, () -> {
            sharesEnd = null;
            if (st.hasVacancy() && !st.recruitingHeld && !st.seats.isEmpty()) {
                discoverAfresh.run();
            }
        });
    }

    /**
     * Whether this manager has more than one open seat of some role: it gives them one after another,
     * each assignment followed by its role's files on its radio, so its last assignments reach their
     * vehicles tens of ms after it chose them, while its siblings, looking for vehicles of the same
     * role, still hear them free. A manager with one seat of each role sends each assignment at once.
     */
    private boolean severalOfOneRole() {
        Map<String, Integer> open = new HashMap<>();
        st.owned.keySet().stream().filter(st::open).forEach(s -> open.merge(s.role(), 1, Integer::sum));
        return open.values().stream().anyMatch(n -> n > 1);
    }

    /**
     * Puts the vehicles that answered this cell's discovery within the first retransmission
     * timeout of the critical messages, and are neither its children nor being given a seat, to the
     * policies again, while a seat is open: managers of the same role hear the same free vehicles,
     * and the one that lost a vehicle to another need not discover again (a round trip) to find the
     * others that answered it. A vehicle that turns out taken refuses, and is forgotten
     * (Recruiter.assignmentFailed).
     */
    void decideOnHeard() {
        long now = ctx.clock().nowMillis();
        long window = ctx.timing().senderSettings().initialTimeoutMillis();
        List<String> recent = Stream.concat(st.heard.keySet().stream(), st.unchecked.keySet().stream()).distinct()
                .filter(v -> now - answeredMillis(v, now) <= window)
                .filter(v -> st.owned.values().stream().noneMatch(o -> v.equals(o.pendingFor))).toList();
        decideOn(recent, now);
    }

    /** When {@code vehicle} last answered (its reply held unchecked, or checked); long ago when it did not. */
    private long answeredMillis(String vehicle, long now) {
        Unchecked u = st.unchecked.get(vehicle);
        Heard h = st.heard.get(vehicle);
        long at = Math.max(u == null ? Long.MIN_VALUE : u.atMillis(), h == null ? Long.MIN_VALUE : h.atMillis());
        return at == Long.MIN_VALUE ? now - Long.MAX_VALUE / 2 : at;
    }

    /**
     * Decides on {@code vehicles} in this manager's order while a seat is open; a vehicle whose reply
     * is held unchecked is checked first, and skipped if it fails: so only as many replies are
     * checked (and as many first contacts made) as it takes to fill the open seats.
     */
    private void decideOn(List<String> vehicles, long now) {
        Optional<Seat> first = st.owned.keySet().stream().filter(st::open).min(ctx.slots()::compare);
        if (first.isEmpty()) {
            return;
        }
        for (String vehicle : SiblingOrder.of(vehicles, first.get(), ctx.slots())) {
            if (!st.hasVacancy()) {
                return;
            }
            if (answeredMillis(vehicle, now) < st.ownShareUntilMillis && !SiblingOrder.inOwnShare(vehicle, first.get(), ctx.slots())) {
                continue; // another sibling's share, and no answer since its owner had its time (beginOwnShare)
            }
            if (!check(vehicle)) {
                continue;
            }
            Heard heard = st.heard.get(vehicle);
            if (heard != null) {
                decision.decide(vehicle, heard.summary(), now);
            }
        }
    }

    /** The cell stops: replies not yet decided on are dropped. */
    void stop() {
        if (burstDue != null) {
            burstDue.cancel();
            burstDue = null;
        }
        burst.clear();
        if (sharesEnd != null) {
            sharesEnd.cancel();
            sharesEnd = null;
        }
    }
}
