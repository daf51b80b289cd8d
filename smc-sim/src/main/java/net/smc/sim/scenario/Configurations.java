package net.smc.sim.scenario;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.TreeMap;

import net.smc.core.cell.Cell;
import net.smc.core.cell.MissionState;
import net.smc.core.cell.Seat;
import net.smc.sim.team.TeamSimulation;

/**
 * Names a team's configuration: which vehicle holds which roles ({@code s1: surveyor+hdetector+relay})
 * and, by the acting commander's mission state, how it stands: {@code forming} below the minimal
 * configuration, {@code minimal} when it holds the minimal one with every surveyor carrying both
 * secondary roles (the paper's Fig. 1), {@code grown} between that and the reasonably-optimal one,
 * {@code optimal} at the reasonably-optimal one (Fig. 2).
 */
final class Configurations {
    /** One snapshot: the roles of each vehicle that holds any, and the standing. */
    record Snapshot(Map<String, List<String>> roles, String standing) {
        /** {@code minimal: a1 aggregator, s1 surveyor+hdetector+relay, ...}. */
        String describe() {
            List<String> parts = new ArrayList<>();
            roles.forEach((v, r) -> parts.add(v + " " + String.join("+", r)));
            return standing + ": " + String.join(", ", parts);
        }
    }

    private Configurations() {
    }

    static Snapshot of(TeamSimulation team) {
        Map<String, List<String>> roles = new TreeMap<>();
        Optional<MissionState> state = Optional.empty();
        for (Cell c : team.cells()) {
            List<String> held = new ArrayList<>();
            for (Seat s : c.seats()) {
                if (!held.contains(s.role())) {
                    held.add(s.role());
                }
            }
            if (!held.isEmpty()) {
                roles.put(c.vehicle(), held);
            }
            if (c.isActingCommander()) {
                state = c.missionState();
            }
        }
        return new Snapshot(roles, standing(state, roles));
    }

    private static String standing(Optional<MissionState> state, Map<String, List<String>> roles) {
        if (state.isEmpty() || state.get() == MissionState.FORMING) {
            return "forming";
        }
        if (state.get() == MissionState.OPTIMAL) {
            return "optimal";
        }
        boolean fig1 = roles.values().stream().filter(r -> r.contains("surveyor")).allMatch(
                r -> r.contains("hdetector") && r.contains("relay"))
                && roles.values().stream().noneMatch(r -> !r.contains("surveyor") && (r.contains("hdetector") || r.contains("relay")));
        return fig1 ? "minimal" : "grown";
    }
}
