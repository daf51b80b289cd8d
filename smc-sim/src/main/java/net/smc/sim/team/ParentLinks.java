package net.smc.sim.team;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.function.BiPredicate;
import java.util.function.Function;
import java.util.function.Predicate;

import net.smc.core.cell.Cell;

/**
 * The parent links of the live cells as one invariant check reads them: each cell's parent, lease
 * and command are read once into arrays, and each parent is asked at most once whether it lists a
 * cell, so that the check's walks up the tree (for cycles, for the teams, for dangling leases) are
 * walks over arrays instead of calls into a thousand cells each. A snapshot: it does not follow the
 * cells after it was made. Generic in what a cell is ({@link Cell} in a simulation, a stand-in in tests).
 *
 * @param <C> the cells
 */
final class ParentLinks<C> {
    /** Steps up from a cell after which its walk to a commander is given up: it is not attached. */
    static final int ROOT_WALK_LIMIT = 64;

    private final List<C> cells;
    private final String[] vehicle;
    private final BiPredicate<C, String> hasChild;
    /** Each cell's parent as it names it (null: none), and that parent's index among the live cells (-1: none, or not live). */
    private final String[] parent;
    private final int[] up;
    private final boolean[] acting;
    private final boolean[] suspended;
    /** Whether each cell's parent lists it: 0 not asked yet, 1 yes, 2 no. */
    private final byte[] listed;

    /** The links of live simulated cells. */
    static ParentLinks<Cell> of(List<Cell> cells) {
        return new ParentLinks<>(cells, Cell::vehicle, c -> c.parent().orElse(null), Cell::isActingCommander,
                Cell::isSuspended, Cell::hasChild);
    }

    /**
     * @param parent a cell's parent as it names it, or null
     * @param hasChild whether a cell lists the vehicle as its child (asked at most once per child)
     */
    ParentLinks(List<C> cells, Function<C, String> vehicleOf, Function<C, String> parentOf, Predicate<C> actingOf,
                Predicate<C> suspendedOf, BiPredicate<C, String> hasChild) {
        this.cells = cells;
        this.hasChild = hasChild;
        int n = cells.size();
        vehicle = new String[n];
        Map<String, Integer> index = new HashMap<>(2 * n);
        for (int i = 0; i < n; i++) {
            vehicle[i] = vehicleOf.apply(cells.get(i));
            index.put(vehicle[i], i);
        }
        parent = new String[n];
        up = new int[n];
        acting = new boolean[n];
        suspended = new boolean[n];
        listed = new byte[n];
        for (int i = 0; i < n; i++) {
            C c = cells.get(i);
            parent[i] = parentOf.apply(c);
            Integer p = parent[i] == null ? null : index.get(parent[i]);
            up[i] = p == null ? -1 : p;
            acting[i] = actingOf.test(c);
            suspended[i] = suspendedOf.test(c);
        }
    }

    int size() {
        return cells.size();
    }

    C cell(int i) {
        return cells.get(i);
    }

    String vehicle(int i) {
        return vehicle[i];
    }

    String parent(int i) {
        return parent[i];
    }

    boolean acting(int i) {
        return acting[i];
    }

    boolean suspended(int i) {
        return suspended[i];
    }

    /** Whether cell {@code i}'s parent is live and lists it among its children. */
    boolean listedByParent(int i) {
        if (up[i] < 0) {
            return false;
        }
        if (listed[i] == 0) {
            listed[i] = hasChild.test(cells.get(up[i]), vehicle[i]) ? (byte) 1 : (byte) 2;
        }
        return listed[i] == 1;
    }

    /**
     * The vehicles on a cycle of the parent relation, or null when there is none. A walk up the
     * parents that meets no cell twice takes at most one step per cell, so only a walk longer than
     * that can have met one: then the walk is made again, remembering the cells met, to name them. A
     * walk that reaches a cell an earlier walk passed through ends there: from that cell on, the way
     * up is known to end.
     */
    Set<String> cycle() {
        int n = cells.size();
        boolean[] ending = new boolean[n];
        int[] walked = new int[n + 1];
        for (int c = 0; c < n; c++) {
            int steps = 0;
            int at = c;
            while (!ending[at] && up[at] >= 0) {
                if (steps >= n) {
                    return nameCycle(c);
                }
                walked[steps++] = at;
                at = up[at];
            }
            for (int k = 0; k < steps; k++) {
                ending[walked[k]] = true;
            }
        }
        return null;
    }

    private Set<String> nameCycle(int from) {
        Set<String> seen = new HashSet<>();
        int at = from;
        while (at >= 0 && seen.add(vehicle[at])) {
            at = up[at];
        }
        return seen;
    }

    /**
     * Attached cells by the acting commander they hang from: every cell on the way up holds a live
     * lease (not suspended) from a parent that lists it as a child, and the walk ends at an acting
     * commander within {@value #ROOT_WALK_LIMIT} steps. Each link is walked once, not once per cell
     * below it.
     */
    Map<String, List<C>> teams() {
        int n = cells.size();
        // Per cell, once known: the index of the commander its walk ends at (-1: none) and the steps.
        int[] end = new int[n];
        int[] steps = new int[n];
        byte[] state = new byte[n];   // 0 not walked, 1 on the way (a walk that meets it again never ends), 2 known
        int[] below = new int[n];
        Map<String, List<C>> teams = new TreeMap<>();
        for (int c = 0; c < n; c++) {
            int depth = 0;
            int at = c;
            int endAt;
            int endSteps;
            while (true) {
                if (state[at] == 2) {
                    endAt = end[at];
                    endSteps = steps[at];
                    break;
                }
                if (state[at] == 1) {
                    endAt = -1;
                    endSteps = ROOT_WALK_LIMIT;
                    break;
                }
                if (acting[at]) {
                    endAt = at;
                    endSteps = 0;
                    state[at] = 2;
                    end[at] = at;
                    steps[at] = 0;
                    break;
                }
                if (suspended[at] || !listedByParent(at)) {
                    endAt = -1;
                    endSteps = 0;
                    state[at] = 2;
                    end[at] = -1;
                    steps[at] = 0;
                    break;
                }
                state[at] = 1;
                below[depth++] = at;
                at = up[at];
            }
            for (int k = depth - 1; k >= 0; k--) {
                if (endSteps + 1 >= ROOT_WALK_LIMIT) {
                    endAt = -1;
                    endSteps = ROOT_WALK_LIMIT;
                } else {
                    endSteps++;
                }
                state[below[k]] = 2;
                end[below[k]] = endAt;
                steps[below[k]] = endSteps;
            }
            if (state[c] == 2 && end[c] >= 0 && steps[c] < ROOT_WALK_LIMIT) {
                teams.computeIfAbsent(vehicle[end[c]], k -> new ArrayList<>()).add(cells.get(c));
            }
        }
        return teams;
    }
}
