package net.smc.core.team;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * Fills the minimal team configuration: for each role, in planning order (primary roles first),
 * as many holders as its minimal cardinality. It is a depth-first search whose first path is the
 * greedy choice, so that the usual case costs one pass; it backs out of a choice only when a later
 * role cannot be filled. That makes it exact: it finds a minimal configuration whenever one
 * exists, which greed alone does not (the vehicle it hands the commander role may be the only
 * possible surveyor; covering secondary roles with few primary vehicles is a set cover).
 *
 * <p>Vehicles of one capability class in the same state are interchangeable, so a role's holders
 * are chosen as a multiset of such groups, never as permutations of equal vehicles. Worst cases
 * remain exponential (the problem contains set cover), so the search stops after
 * {@link #BUDGET} choices and the planner falls back to the greedy partial fill; the budget is a
 * count, not a time, so that the answer stays deterministic.
 */
final class MinimalSearch {
    /** Choices the exact search may try before it gives up (small teams need a few hundred at most). */
    static final int BUDGET = 100_000;

    private static final int TAKE = 0;
    private static final int PROMOTE = 1;
    private static final int CARRY = 2;

    private final Board board;
    private final RoleTable roles;
    private final Fleet fleet;
    private int choices;

    MinimalSearch(Board board) {
        this.board = board;
        this.roles = board.roles;
        this.fleet = board.fleet;
    }

    /** Vehicles that can serve a role the same way: one kind of choice, one capability class, one state. */
    private record Group(int kind, int[] members, int flexibility, int carries) {
    }

    /** Thrown, without a stack trace, when the budget runs out. */
    private static final class OutOfBudget extends RuntimeException {
        OutOfBudget() {
            super(null, null, false, false);
        }
    }

    /**
     * Searches for a minimal configuration on top of what the board holds.
     *
     * @return whether the board now meets the minimal configuration; when not (there is none, or
     *         the budget ran out) the board is left in no useful state: search on a copy
     */
    boolean exact() {
        try {
            return fill(0);
        } catch (OutOfBudget e) {
            return false;
        }
    }

    /** Fills what it can without backing out of any choice. */
    void greedy() {
        for (int r : roles.order) {
            int need = roles.min[r] - board.count[r];
            for (Group group : groups(r)) {
                for (int v = next(group, r); need > 0 && v >= 0; v = next(group, r)) {
                    apply(group.kind, v, r);
                    need--;
                }
            }
        }
    }

    private boolean fill(int step) {
        if (step == roles.order.length) {
            return true;
        }
        int r = roles.order[step];
        int need = roles.min[r] - board.count[r];
        if (need <= 0) {
            return fill(step + 1);
        }
        if (!possible(step)) {
            return false;
        }
        return choose(step, r, groups(r), 0, need);
    }

    /** Picks {@code need} more holders of {@code r} from groups {@code from} on (a multiset: never an earlier group). */
    private boolean choose(int step, int r, List<Group> groups, int from, int need) {
        if (need == 0) {
            return fill(step + 1);
        }
        if (++choices > BUDGET) {
            throw new OutOfBudget();
        }
        for (int i = from; i < groups.size(); i++) {
            Group group = groups.get(i);
            int v = next(group, r);
            if (v < 0) {
                continue;
            }
            apply(group.kind, v, r);
            if (choose(step, r, groups, i, need - 1)) {
                return true;
            }
            undo(group.kind, v, r);
        }
        return false;
    }

    /** Necessary conditions for the roles from {@code step} on: enough candidates each, enough free vehicles for the primaries. */
    private boolean possible(int step) {
        int primaryNeed = 0;
        for (int i = step; i < roles.order.length; i++) {
            int t = roles.order[i];
            int need = roles.min[t] - board.count[t];
            if (need <= 0) {
                continue;
            }
            int candidates = board.freeCapable[t] + (roles.isSecondary(t) ? board.carriable[t] : 0);
            if (candidates < need) {
                return false;
            }
            if (!roles.isSecondary(t)) {
                primaryNeed += need;
            }
        }
        return primaryNeed <= board.free;
    }

    /** The lowest vehicle of {@code group} that can still serve {@code r} its way, or -1. */
    private int next(Group group, int r) {
        for (int v : group.members) {
            boolean eligible = switch (group.kind) {
                case TAKE -> board.anchor[v] < 0;
                case PROMOTE -> board.anchor[v] < 0 && board.count[roles.primaryOf[r]] < roles.opt[roles.primaryOf[r]];
                default -> board.canCarry(v, r);
            };
            if (eligible) {
                return v;
            }
        }
        return -1;
    }

    private void apply(int kind, int v, int r) {
        switch (kind) {
            case TAKE -> board.take(v, r);
            case PROMOTE -> {
                board.take(v, roles.primaryOf[r]);
                board.carry(v, r);
            }
            default -> board.carry(v, r);
        }
    }

    private void undo(int kind, int v, int r) {
        switch (kind) {
            case TAKE -> board.untake(v, r);
            case PROMOTE -> {
                board.uncarry(v, r);
                board.untake(v, roles.primaryOf[r]);
            }
            default -> board.uncarry(v, r);
        }
    }

    /**
     * The ways to give {@code r} a holder, best first. A primary role prefers vehicles that can
     * also carry its secondary roles still needed, then the least flexible vehicles (keep versatile
     * ones for roles few can hold). A secondary role rides on a vehicle of its primary first (it
     * saves a vehicle), then takes a vehicle of its own, and last makes a free vehicle a new holder
     * of its primary to ride on.
     */
    private List<Group> groups(int r) {
        int p = roles.primaryOf[r];
        boolean promote = p >= 0 && board.count[p] < roles.opt[p];
        // Pass 1: which group each (vehicle, kind) joins; pass 2: fill the groups' arrays.
        int[] takeGroup = new int[fleet.size()];
        int[] promoteGroup = new int[fleet.size()];
        int[] byTakeClass = new int[fleet.classCount()];
        int[] byPromoteClass = new int[fleet.classCount()];
        Map<String, Integer> byCarryKey = new HashMap<>();
        int[] sizes = new int[8];
        int[] kinds = new int[8];
        int count = 0;
        for (int v = 0; v < fleet.size(); v++) {
            if (!fleet.capable(v, r)) {
                continue;
            }
            int c = fleet.classOf[v];
            if (board.anchor[v] < 0) {
                if (byTakeClass[c] == 0) {
                    byTakeClass[c] = ++count;
                }
                takeGroup[v] = byTakeClass[c];
                if (promote && fleet.capable(v, p)) {
                    if (byPromoteClass[c] == 0) {
                        byPromoteClass[c] = ++count;
                    }
                    promoteGroup[v] = byPromoteClass[c];
                }
            } else if (p >= 0 && board.canCarry(v, r)) {
                // Carriers are interchangeable only if they also hold the same roles.
                String key = c + ":" + java.util.Arrays.toString(board.held[v]);
                Integer g = byCarryKey.get(key);
                if (g == null) {
                    g = ++count;
                    byCarryKey.put(key, g);
                }
                takeGroup[v] = g;
            }
            if (count >= sizes.length) {
                sizes = java.util.Arrays.copyOf(sizes, 2 * sizes.length);
                kinds = java.util.Arrays.copyOf(kinds, 2 * kinds.length);
            }
            if (takeGroup[v] > 0) {
                sizes[takeGroup[v]]++;
                kinds[takeGroup[v]] = board.anchor[v] < 0 ? TAKE : CARRY;
            }
            if (promoteGroup[v] > 0) {
                sizes[promoteGroup[v]]++;
                kinds[promoteGroup[v]] = PROMOTE;
            }
        }
        int[][] members = new int[count + 1][];
        for (int g = 1; g <= count; g++) {
            members[g] = new int[sizes[g]];
            sizes[g] = 0;
        }
        for (int v = 0; v < fleet.size(); v++) {
            if (takeGroup[v] > 0) {
                members[takeGroup[v]][sizes[takeGroup[v]]++] = v;
            }
            if (promoteGroup[v] > 0) {
                members[promoteGroup[v]][sizes[promoteGroup[v]]++] = v;
            }
        }
        List<Group> groups = new ArrayList<>(count);
        for (int g = 1; g <= count; g++) {
            int first = members[g][0];
            groups.add(new Group(kinds[g], members[g], fleet.flexibility[first], p < 0 ? carries(first, r) : 0));
        }
        groups.sort(Comparator.comparingInt((Group g) -> g.kind == CARRY ? 0 : g.kind == TAKE ? 1 : 2)
                .thenComparing(Comparator.comparingInt((Group g) -> g.carries).reversed())
                .thenComparingInt(g -> g.flexibility)
                .thenComparingInt(g -> g.members[0]));
        return groups;
    }

    /** How many still-needed secondary roles of primary {@code r} vehicle {@code v} could carry. */
    private int carries(int v, int r) {
        int n = 0;
        for (int s : roles.secondariesOf[r]) {
            if (board.count[s] < roles.min[s] && fleet.capable(v, s)) {
                n++;
            }
        }
        return n;
    }
}
