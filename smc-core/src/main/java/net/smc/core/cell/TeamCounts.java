package net.smc.core.cell;

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
        Map<String, Integer> counts = ctx.slots().count(st.suspended() ? List.of() : st.seats);
        for (Child c : st.children.values()) {
            Map<String, Integer> sub = c.subtree != null ? c.subtree : ctx.slots().count(c.seats);
            sub.forEach((role, n) -> counts.merge(role, n, Integer::sum));
        }
        return counts;
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
