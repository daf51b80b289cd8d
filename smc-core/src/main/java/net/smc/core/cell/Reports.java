package net.smc.core.cell;

import java.math.BigDecimal;
import java.util.ArrayList;
import java.util.Collections;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.TreeMap;

import net.smc.core.cell.TeamState.Child;
import net.smc.core.cell.TeamState.Owned;
import net.smc.core.message.Envelope;
import net.smc.core.message.Identity;
import net.smc.core.message.Invocation;
import net.smc.core.message.SubtreeReport;

/**
 * Subtree reports and views: a child's report (its counts, seats and state) read into this cell's
 * table, with anti-entropy against the seats it claims; the report this cell sends its parent; and
 * the views the cell and its tests read. Owns SUBTREE_REPORT.
 */
final class Reports {
    private final TeamContext ctx;
    private final TeamState st;
    private final TeamCounts counts;
    private final Recruiter recruiter;
    private static final String SIZE = "#size";
    private static final String HOSTED = "#hosted";

    /**
     * The report last built, and what it was built from: {@link #reportValues} builds it again only
     * when one of those moved. Its inputs are this cell's seats and children and their seats (the
     * link version), the children's own reports ({@link #childReports}), the state set by
     * {@link #reportState}, whether the lease has lapsed, the tasks' states and the mission's slots.
     */
    private List<Object> report;
    private long reportLinks = -1;
    private long reportChildReports = -1;
    private boolean reportSuspended;
    private List<Object> reportTaskStates;
    private Slots reportSlots;
    /** Moves whenever a child's report or this cell's reported state is taken in. */
    private long childReports;

    Reports(TeamContext ctx, TeamState st, TeamCounts counts, Recruiter recruiter) {
        this.ctx = ctx;
        this.st = st;
        this.counts = counts;
        this.recruiter = recruiter;
    }

    void onReport(Envelope env, SubtreeReport e) {
        Child child = st.children.get(env.sender());
        if (child == null) {
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
        int size = counts.getOrDefault(SIZE, 1);
        int hosted = counts.getOrDefault(HOSTED, 0);
        counts.remove(SIZE);
        counts.remove(HOSTED);
        // A report that repeats the last one (most do: an unchanged subtree is reported again every
        // sixteenth heartbeat) moves nothing, so this cell's own report is not built again for it.
        if (size != child.size || hosted != child.hosted || child.subtree == null
                || !sameInOrder(counts, child.subtree) || !state.equals(child.state)) {
            child.size = size;
            child.hosted = hosted;
            child.subtree = counts;
            child.state = state;
            childReports++;
        }
        this.counts.updateMissionState();
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
                    ctx.emit(CellEvent.Kind.REJECTED, child.vehicle + " reports seat '" + name + "'; seats are role#slot");
                }
            }
        }
        List<Seat> mine = new ArrayList<>(child.seats);
        boolean conflict = false;
        for (Seat s : claimed) {
            Owned o = st.owned.get(s);
            if (o == null || child.vehicle.equals(o.holder)) {
                continue;
            }
            if (child.vehicle.equals(o.pendingFor)) {
                recruiter.accepted(child.vehicle, s);
                mine = new ArrayList<>(child.seats);
            } else if (o.holder == null && o.pendingFor == null) {
                o.holder = child.vehicle;
                mine.add(s);
                child.confirmedBy.put(s, reportId);
                ctx.emit(CellEvent.Kind.ASSIGNED, s + " adopted: " + child.vehicle + " reports holding it");
            } else {
                conflict = true;
                ctx.emit(CellEvent.Kind.REJECTED, child.vehicle + " reports " + s + ", which this cell gives "
                        + (o.holder != null ? o.holder : o.pendingFor) + "; taken back");
                ctx.address(child.vehicle).ifPresent(a -> ctx.comm().send(a, new Invocation(s.role(), "release", List.of())));
            }
        }
        for (Seat s : List.copyOf(mine)) {
            if (!claimed.contains(s) && reportId > child.confirmedBy.getOrDefault(s, Long.MIN_VALUE)) {
                mine.remove(s);
                Owned o = st.owned.get(s);
                if (o != null && child.vehicle.equals(o.holder)) {
                    o.holder = null;
                }
            }
        }
        List<Seat> seats = List.copyOf(mine);
        // Only a change of the child's seats or of its agreement with this table is a change of the
        // links: a report that confirms what this cell already holds moves nothing.
        boolean moved = !seats.equals(child.seats) || child.consistent == conflict;
        child.seats = seats;
        child.consistent = !conflict;
        if (moved) {
            st.linksChanged();
        }
    }

    /**
     * The values of the report this cell sends its parent: the held roles' counts in its subtree,
     * its size, how many seats in it are hosted, its seats and its state. Built again only when one
     * of its inputs moved (see {@link #report}); otherwise the same list as last time. With
     * {@link ReportChecks} on, every call also builds it afresh and counts a kept list that differs.
     */
    List<Object> reportValues() {
        boolean suspended = st.suspended();
        List<Object> tasks = ctx.host().taskStates();
        long links = st.linkVersion.getAsLong();
        boolean kept = report != null && links == reportLinks && childReports == reportChildReports
                && suspended == reportSuspended && ctx.slots() == reportSlots && tasks.equals(reportTaskStates);
        if (kept && !ReportChecks.on()) {
            return report;
        }
        List<Object> fresh = buildReport(tasks);
        if (kept) {
            ReportChecks.compared(fresh.equals(report));
            return report;
        }
        report = fresh;
        reportLinks = links;
        reportChildReports = childReports;
        reportSuspended = suspended;
        reportTaskStates = tasks;
        reportSlots = ctx.slots();
        return fresh;
    }

    private List<Object> buildReport(List<Object> taskStates) {
        List<Object> v = new ArrayList<>();
        counts.heldSubtreeCounts().forEach((role, n) -> {
            v.add(role);
            v.add(BigDecimal.valueOf(n));
        });
        v.add(SIZE);
        v.add(BigDecimal.valueOf(counts.subtreeSize()));
        v.add(HOSTED);
        v.add(BigDecimal.valueOf(counts.hostedCount()));
        v.add("#seats");
        v.add(st.seats.stream().map(Seat::toString).toList());
        List<Object> state = new ArrayList<>(st.reportedState);
        state.addAll(taskStates);
        if (!state.isEmpty() && v.size() < 60) {
            v.add("#state");
            v.add(state);
        }
        return Collections.unmodifiableList(v);
    }

    /** Sets the state this vehicle reports to its parent (its position, say), handed over if it fails. */
    void reportState(List<Object> state) {
        st.reportedState = List.copyOf(state);
        childReports++;
    }

    List<Object> handedOver() {
        return st.handedOver;
    }

    boolean acting() {
        return st.acting;
    }

    /** Whether the lease from the parent has run out: this cell's seats do not count until renewed. */
    boolean suspended() {
        return st.parent != null && !st.acting && ctx.clock().nowMillis() > st.leaseUntilMillis;
    }

    long epoch() {
        return st.epoch;
    }

    Optional<String> parent() {
        return st.parent == null ? Optional.empty() : Optional.of(st.parent.vehicle());
    }

    List<Seat> seats() {
        return List.copyOf(st.seats);
    }

    boolean holdsSeats(List<Seat> seats) {
        return st.seats.equals(seats);
    }

    String parentOrNull() {
        return st.parent == null ? null : st.parent.vehicle();
    }

    Optional<Identity> identity() {
        return Optional.ofNullable(st.identity);
    }

    Map<String, List<Seat>> children() {
        Map<String, List<Seat>> out = new TreeMap<>();
        st.children.forEach((v, c) -> {
            if (!c.seats.isEmpty()) {
                out.put(v, c.seats);
            }
        });
        return out;
    }

    /** Whether {@code vehicle} is a child holding a seat from this cell: a key of {@link #children()}. */
    boolean hasChild(String vehicle) {
        Child c = st.children.get(vehicle);
        return c != null && !c.seats.isEmpty();
    }

    Optional<String> commander() {
        return Optional.ofNullable(st.commander);
    }

    Optional<MissionState> missionState() {
        return Optional.ofNullable(st.missionState);
    }

    /** Messages refused, by reason. */
    Map<String, Long> rejected() {
        return ctx.rejected();
    }

    boolean left() {
        return st.left;
    }

    CellView view() {
        Map<String, List<String>> kids = new TreeMap<>();
        children().forEach((v, s) -> kids.put(v, s.stream().map(Seat::toString).toList()));
        return new CellView(ctx.self(), ctx.missionId(), st.identity == null ? null : st.identity.toString(), st.epoch, st.commander, st.acting,
                st.parent == null ? null : st.parent.vehicle(), suspended(), st.seats.stream().map(Seat::toString).toList(), kids,
                st.acting ? st.missionState : null, st.acting ? counts.subtreeCounts() : Map.of(), ctx.clock().nowMillis());
    }

    /** Whether two maps hold the same entries in the same order (a report's counts keep its order), without copying them. */
    private static boolean sameInOrder(Map<String, Integer> a, Map<String, Integer> b) {
        if (a.size() != b.size()) {
            return false;
        }
        Iterator<Map.Entry<String, Integer>> other = b.entrySet().iterator();
        for (Map.Entry<String, Integer> e : a.entrySet()) {
            if (!e.equals(other.next())) {
                return false;
            }
        }
        return true;
    }
}
