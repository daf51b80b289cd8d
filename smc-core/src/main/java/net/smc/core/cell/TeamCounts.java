package net.smc.core.cell;

import java.util.ArrayList;
import java.util.Collection;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import net.smc.core.cell.TeamState.Child;
import net.smc.core.mission.Mission;
import net.smc.core.mission.MissionRole;

/**
 * Holders per role in this cell's subtree, the subtree's size, and for the acting commander the
 * mission's state (FORMING, RUNNING, OPTIMAL), raised as {@code missionState} when it changes.
 */
final class TeamCounts {
    private final TeamContext ctx;
    private final TeamState st;

    TeamCounts(TeamContext ctx, TeamState st) {
        this.ctx = ctx;
        this.st = st;

    }

    /** Holders per role in this cell's subtree, itself included (suspended holders do not count). */
    Map<String, Integer> subtreeCounts() {
        return subtreeCounts(ctx.slots(), st.suspended() ? List.of() : st.seats, st.children.values());
    }

    /** Holders per role of {@code own} seats and of {@code children}'s subtrees, every role of the mission present. */
    static Map<String, Integer> subtreeCounts(Slots slots, List<Seat> own, Collection<Child> children) {
        Map<String, Integer> counts = slots.count(own);
        for (Child c : children) {
            if (c.subtree != null) {
                c.subtree.forEach((role, n) -> counts.merge(role, n, Integer::sum));
            } else {
                // A child's own seats, merged one by one: a map of every role of the mission per child
                // made a commander of a thousand children and roles do a million merges a tick.
                c.seats.forEach(s -> counts.merge(s.role(), 1, Integer::sum));
            }
        }
        return counts;
    }

    /**
     * The entries of {@link #subtreeCounts()} with a count above zero, in the same order (the
     * mission's roles breadth-first, then any other name in the order first met), summed over the
     * roles actually held instead of over a map of every role of the mission: what a report carries,
     * made twice a second by every cell of a team whose mission may have a thousand roles.
     */
    Map<String, Integer> heldSubtreeCounts() {
        return heldSubtreeCounts(ctx.slots(), st.suspended() ? List.of() : st.seats, st.children.values());
    }

    /** {@link #subtreeCounts(Slots, List, Collection)}'s entries above zero, in its order. */
    static Map<String, Integer> heldSubtreeCounts(Slots slots, List<Seat> own, Collection<Child> children) {
        Map<String, Integer> sums = new LinkedHashMap<>();
        own.forEach(s -> sums.merge(s.role(), 1, Integer::sum));
        for (Child c : children) {
            if (c.subtree != null) {
                c.subtree.forEach((role, n) -> sums.merge(role, n, Integer::sum));
            } else {
                c.seats.forEach(s -> sums.merge(s.role(), 1, Integer::sum));
            }
        }
        List<Map.Entry<String, Integer>> entries = new ArrayList<>(sums.entrySet());
        entries.sort(Comparator.comparingInt(e -> slots.rankOrLast(e.getKey())));   // stable: other names keep their order
        Map<String, Integer> out = new LinkedHashMap<>();
        for (Map.Entry<String, Integer> e : entries) {
            if (e.getValue() > 0) {
                out.put(e.getKey(), e.getValue());
            }
        }
        return out;
    }

    int hostedCount() {
        int n = st.suspended() ? 0 : (int) st.seats.stream().filter(s -> st.hosted(s, ctx.self())).count();
        for (Child c : st.children.values()) {
            n += c.hosted;
        }
        return n;
    }

    int teamSize() {
        return st.acting ? subtreeSize() : st.teamSize;
    }

    int subtreeSize() {
        int n = 1;
        for (Child c : st.children.values()) {
            n += c.size;
        }
        return n;
    }

    void updateMissionState() {
        if (!st.acting) {
            return;
        }
        Map<String, Integer> counts = subtreeCounts();
        MissionState next = MissionState.OPTIMAL;
        for (String role : ctx.slots().roles()) {
            int n = counts.getOrDefault(role, 0);
            MissionRole r = ctx.slots().role(role);
            int min = role.equals(Mission.COMMANDER) ? 1 : r.minimal();
            if (n < min) {
                next = MissionState.FORMING;
                break;
            }
            if (n < ctx.slots().optimal(role)) {
                next = MissionState.RUNNING;
            }
        }
        if (next == MissionState.OPTIMAL && hostedCount() > 0) {
            next = MissionState.RUNNING;
        }
        if (next != st.missionState) {
            st.missionState = next;
            ctx.emit(CellEvent.Kind.MISSION_STATE, next + " " + counts + " hosted " + hostedCount());
            ctx.host().raise("missionState", "missionState", next.name().toLowerCase());
        }
    }
}
