package net.smc.core.team;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import net.smc.core.mission.Colocation;
import net.smc.core.mission.Mission;
import net.smc.core.mission.MissionRole;

/**
 * A mission's roles as arrays indexed by role number (the mission's role order), so that the
 * planner's inner loops index instead of looking names up.
 */
final class RoleTable {
    final Mission mission;
    final String[] names;
    final int[] min;
    final int[] opt;
    /** The primary role of each secondary role; -1 for primary roles. */
    final int[] primaryOf;
    /** The secondary roles of each primary role, in planning order. */
    final int[][] secondariesOf;
    /** Whether two roles may share a vehicle (a parallel or exclusive rule pairs them). */
    final boolean[][] share;
    /** Planning order: primary roles breadth-first from the commander, then secondary roles breadth-first. */
    final int[] order;
    final int commander;
    /** How many longs a bitset over the roles takes. */
    final int words;
    private final Map<String, Integer> index = new HashMap<>();

    RoleTable(Mission mission) {
        this.mission = mission;
        List<MissionRole> roles = mission.roles();
        int n = roles.size();
        names = new String[n];
        min = new int[n];
        opt = new int[n];
        primaryOf = new int[n];
        share = new boolean[n][n];
        words = (n + 63) / 64;
        for (int r = 0; r < n; r++) {
            MissionRole role = roles.get(r);
            names[r] = role.name();
            min[r] = role.minimal();
            opt[r] = role.optimal();
            index.put(role.name(), r);
        }
        for (int r = 0; r < n; r++) {
            primaryOf[r] = roles.get(r).primary().map(index::get).orElse(-1);
        }
        // From the rules directly: asking Colocation.mayShare for every pair costs rules x roles^2.
        for (Colocation.Parallel rule : mission.colocation().parallel()) {
            for (String with : rule.with()) {
                pair(index.get(rule.role()), index.get(with));
            }
        }
        for (Colocation.Exclusive rule : mission.colocation().exclusive()) {
            for (String a : rule.roles()) {
                for (String b : rule.roles()) {
                    pair(index.get(a), index.get(b));
                }
            }
        }
        commander = index.get(Mission.COMMANDER);
        List<String> breadthFirst = mission.tree().breadthFirst();
        order = new int[n];
        int at = 0;
        for (boolean secondaries : new boolean[] {false, true}) {
            for (String name : breadthFirst) {
                int r = index.get(name);
                if ((primaryOf[r] >= 0) == secondaries) {
                    order[at++] = r;
                }
            }
        }
        secondariesOf = new int[n][];
        for (int p = 0; p < n; p++) {
            List<Integer> found = new ArrayList<>();
            for (int r : order) {
                if (primaryOf[r] == p) {
                    found.add(r);
                }
            }
            secondariesOf[p] = found.stream().mapToInt(Integer::intValue).toArray();
        }
    }

    private void pair(int a, int b) {
        if (a != b) {
            share[a][b] = true;
            share[b][a] = true;
        }
    }

    int size() {
        return names.length;
    }

    boolean isSecondary(int r) {
        return primaryOf[r] >= 0;
    }
}
