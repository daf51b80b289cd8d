package net.smc.sim.team;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.function.BiPredicate;
import java.util.function.Function;
import java.util.function.Predicate;

import net.smc.core.cell.Cell;
import net.smc.core.cell.Seat;

/**
 * Everything the structural invariant rules (no cycle, no seat with two holders in a team, no slot
 * beyond its role's cardinality, every attached holder capable) read of the live cells, kept from
 * one check to the next: which cells are live, each one's parent, whether it acts as commander,
 * whether its lease ran out, whether its parent lists it as a child, and the seats it holds. Those
 * rules are functions of these readings alone (the mission and the vehicles' kits are fixed), so
 * when a check reads exactly what the last <em>passed</em> check read, they hold again and need not
 * be walked: an idle team re-reads a few fields per cell instead of building maps and walking the
 * tree every 50 ms. Any change, in any cell, makes {@link #read} say so, and the rules are walked
 * in full. The time-bound rules (dangling leases, commanders that hear each other) are evaluated
 * at every check from these readings ({@link #parent}, {@link #acting}, ...).
 *
 * <p>Generic in what a cell is ({@link Cell} in a simulation, a stand-in in tests).
 *
 * @param <C> the cells
 */
final class CellReadings<C> {
    private final Function<C, String> vehicleOf;
    private final Function<C, String> parentOf;
    private final Predicate<C> actingOf;
    private final Predicate<C> suspendedOf;
    private final BiPredicate<C, String> hasChild;
    private final Function<C, List<Seat>> seatsOf;
    private final BiPredicate<C, List<Seat>> holdsSeats;

    private List<C> cells = List.of();
    private final List<C> live = new ArrayList<>();
    private final Map<String, Integer> index = new HashMap<>();
    private String[] vehicle = new String[0];
    private String[] parent = new String[0];
    private boolean[] acting = new boolean[0];
    private boolean[] suspended = new boolean[0];
    private boolean[] listed = new boolean[0];
    private List<List<Seat>> seats = new ArrayList<>();
    /** Whether the structural rules passed on the readings as they stand. */
    private boolean passed;

    /** The readings of live simulated cells. */
    static CellReadings<Cell> ofCells() {
        return new CellReadings<>(Cell::vehicle, Cell::parentOrNull, Cell::isActingCommander, Cell::isSuspended,
                Cell::hasChild, Cell::seats, Cell::holdsSeats);
    }

    /**
     * @param parentOf   a cell's parent as it names it, or null
     * @param hasChild   whether a cell lists the vehicle as its child
     * @param seatsOf    a copy of the seats a cell holds
     * @param holdsSeats whether a cell holds exactly the seats given (as {@code seatsOf(c).equals(seats)})
     */
    CellReadings(Function<C, String> vehicleOf, Function<C, String> parentOf, Predicate<C> actingOf,
                 Predicate<C> suspendedOf, BiPredicate<C, String> hasChild, Function<C, List<Seat>> seatsOf,
                 BiPredicate<C, List<Seat>> holdsSeats) {
        this.vehicleOf = vehicleOf;
        this.parentOf = parentOf;
        this.actingOf = actingOf;
        this.suspendedOf = suspendedOf;
        this.hasChild = hasChild;
        this.seatsOf = seatsOf;
        this.holdsSeats = holdsSeats;
    }

    /**
     * Reads every cell of {@code now} (the live cells, in the simulation's order).
     *
     * @return whether the structural rules must be walked: something differs from the readings of
     *     the last check that {@linkplain #passed() passed} them, or none did yet
     */
    boolean read(List<C> now) {
        boolean same = sameCells(now);
        if (!same) {
            adopt(now);
        }
        int n = live.size();
        for (int i = 0; i < n; i++) {
            C c = live.get(i);
            String p = parentOf.apply(c);
            if (!Objects.equals(p, parent[i])) {
                parent[i] = p;
                same = false;
            }
            boolean a = actingOf.test(c);
            boolean s = suspendedOf.test(c);
            if (a != acting[i] || s != suspended[i]) {
                acting[i] = a;
                suspended[i] = s;
                same = false;
            }
            Integer up = p == null ? null : index.get(p);
            boolean l = up != null && hasChild.test(live.get(up), vehicle[i]);
            if (l != listed[i]) {
                listed[i] = l;
                same = false;
            }
            if (!holdsSeats.test(c, seats.get(i))) {
                seats.set(i, List.copyOf(seatsOf.apply(c)));
                same = false;
            }
        }
        if (!same) {
            passed = false;
        }
        return !passed;
    }

    /** Records that the structural rules held on the readings as they stand. */
    void passed() {
        passed = true;
    }

    private boolean sameCells(List<C> now) {
        if (now.size() != live.size()) {
            return false;
        }
        for (int i = 0; i < now.size(); i++) {
            if (now.get(i) != live.get(i)) {
                return false;
            }
        }
        return true;
    }

    /** A new set of live cells: everything is read afresh (null parents and empty seats are re-read below). */
    private void adopt(List<C> now) {
        cells = now;
        live.clear();
        live.addAll(now);
        int n = now.size();
        index.clear();
        vehicle = new String[n];
        parent = new String[n];
        acting = new boolean[n];
        suspended = new boolean[n];
        listed = new boolean[n];
        seats = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
            vehicle[i] = vehicleOf.apply(now.get(i));
            index.put(vehicle[i], i);
            seats.add(List.of());
        }
        passed = false;
    }

    /** The cells of the latest reading. */
    List<C> cells() {
        return cells;
    }

    int size() {
        return live.size();
    }

    String vehicle(int i) {
        return vehicle[i];
    }

    /** Cell {@code i}'s parent as it names it, or null. */
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
        return listed[i];
    }

    /** The acting commanders, in the cells' order. */
    List<C> commanders() {
        List<C> out = new ArrayList<>();
        for (int i = 0; i < live.size(); i++) {
            if (acting[i]) {
                out.add(live.get(i));
            }
        }
        return out;
    }
}
