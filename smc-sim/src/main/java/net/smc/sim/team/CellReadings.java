package net.smc.sim.team;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.function.BiPredicate;
import java.util.function.Function;
import java.util.function.Predicate;
import java.util.function.ToLongFunction;

import net.smc.core.cell.Cell;
import net.smc.core.cell.Seat;

/**
 * Everything the structural invariant rules (no cycle, no seat with two holders in a team, no slot
 * beyond its role's cardinality, every attached holder capable) read of the live cells, kept from
 * one check to the next: which cells are live, each one's parent, whether it acts as commander,
 * whether its lease ran out, whether its parent lists it as a child, and the seats it holds.
 *
 * <p><b>Driven by the cells' changes.</b> A cell's {@linkplain Cell#linkVersion() link version}
 * grows whenever its parent, command, seats, children or their seats change, or its lease is set
 * other than by a renewal, and the simulation tells these readings so ({@link #moved}, from
 * {@link Cell#onLinksChanged}). A check re-reads only the cells that moved, and whether a cell is
 * listed by its parent only when the cell or its parent moved; it visits no other cell.
 * The lease is the one reading that changes without the version: a cell whose lease, as last read,
 * has run out ({@code now > leaseUntil}), or that was suspended, is read again (its lease was
 * renewed, or it lapsed). With {@link #verifying} on, every check also reads every cell in
 * full and fails, naming the cell and the reading, if the incremental readings differ (for tests:
 * a writer that forgot to move the version would show there).
 *
 * <p><b>Skipping the walk.</b> The structural rules are functions of these readings alone (the
 * mission and the vehicles' kits are fixed), so when a check reads exactly what the last
 * <em>passed</em> check read ({@link #read} returns false), they hold again and need not be walked.
 * The time-bound rules (dangling leases, commanders that hear each other) are evaluated at every
 * check from the readings ({@link #parent}, {@link #acting}, ...).
 *
 * <p>Generic in what a cell is ({@link Cell} in a simulation, a stand-in in tests).
 *
 * @param <C> the cells
 */
final class CellReadings<C> {
    /** What is read of one cell. */
    record Reader<C>(Function<C, String> vehicle, Function<C, String> parent,
                     Predicate<C> acting, Predicate<C> suspended, ToLongFunction<C> leaseUntil,
                     BiPredicate<C, String> hasChild, Function<C, List<Seat>> seats, BiPredicate<C, List<Seat>> holdsSeats) {
    }

    private final Reader<C> reader;
    private boolean verifying;

    private List<C> cells = List.of();
    private final List<C> live = new ArrayList<>();
    private final Map<String, Integer> index = new HashMap<>();
    private String[] vehicle = new String[0];
    /** Each live cell's position, to mark the ones that moved. */
    private final Map<C, Integer> position = new IdentityHashMap<>();
    /** The cells that moved since the last read (told by {@link #moved}). */
    private boolean[] told = new boolean[0];
    private String[] parent = new String[0];
    /** The parent's index among the live cells, -1 when none or not live. */
    private int[] up = new int[0];
    private boolean[] acting = new boolean[0];
    private boolean[] suspended = new boolean[0];
    private long[] leaseUntil = new long[0];
    private boolean[] listed = new boolean[0];
    private boolean[] moved = new boolean[0];
    private List<List<Seat>> seats = new ArrayList<>();
    /** Whether the structural rules passed on the readings as they stand. */
    private boolean passed;
    private long reread;

    /** The readings of live simulated cells. */
    static CellReadings<Cell> ofCells() {
        return new CellReadings<>(new Reader<>(Cell::vehicle, Cell::parentOrNull,
                Cell::isActingCommander, Cell::isSuspended, Cell::leaseUntilMillis, Cell::hasChild, Cell::seats,
                Cell::holdsSeats));
    }

    CellReadings(Reader<C> reader) {
        this.reader = reader;
    }

    /** With {@code on}, every {@link #read} checks its readings against a full read of every cell. */
    CellReadings<C> verifying(boolean on) {
        this.verifying = on;
        return this;
    }

    /**
     * Brings the readings up to date with {@code now} (the live cells, in the simulation's order) at
     * time {@code nowMillis}.
     *
     * @return whether the structural rules must be walked: something differs from the readings of
     *     the last check that {@linkplain #passed() passed} them, or none did yet
     */
    boolean read(List<C> now, long nowMillis) {
        boolean same = sameCells(now);
        boolean all = !same;
        if (all) {
            adopt(now);
        }
        int n = live.size();
        for (int i = 0; i < n; i++) {
            C c = live.get(i);
            moved[i] = all || told[i];
            told[i] = false;
            if (moved[i]) {
                reread++;
                same &= readOwn(i, c);
            } else if (parent[i] != null && !acting[i] && (suspended[i] || nowMillis > leaseUntil[i])) {
                // The lease read has run out: renewed since (a renewal moves no version), or lapsed.
                leaseUntil[i] = reader.leaseUntil.applyAsLong(c);
                boolean s = reader.suspended.test(c);
                if (s != suspended[i]) {
                    suspended[i] = s;
                    same = false;
                }
            }
        }
        for (int i = 0; i < n; i++) {
            if (moved[i] || up[i] >= 0 && moved[up[i]]) {
                boolean l = up[i] >= 0 && reader.hasChild.test(live.get(up[i]), vehicle[i]);
                if (l != listed[i]) {
                    listed[i] = l;
                    same = false;
                }
            }
        }
        if (verifying) {
            verify(nowMillis);
        }
        if (!same) {
            passed = false;
        }
        return !passed;
    }

    /** Re-reads cell {@code i}'s own fields; returns whether they are as they were. */
    private boolean readOwn(int i, C c) {
        boolean same = true;
        String p = reader.parent.apply(c);
        if (!Objects.equals(p, parent[i])) {
            parent[i] = p;
            Integer at = p == null ? null : index.get(p);
            up[i] = at == null ? -1 : at;
            same = false;
        }
        boolean a = reader.acting.test(c);
        boolean s = reader.suspended.test(c);
        if (a != acting[i] || s != suspended[i]) {
            acting[i] = a;
            suspended[i] = s;
            same = false;
        }
        leaseUntil[i] = reader.leaseUntil.applyAsLong(c);
        if (!reader.holdsSeats.test(c, seats.get(i))) {
            seats.set(i, List.copyOf(reader.seats.apply(c)));
            same = false;
        }
        return same;
    }

    private void verify(long nowMillis) {
        for (int i = 0; i < live.size(); i++) {
            C c = live.get(i);
            String p = reader.parent.apply(c);
            Integer at = p == null ? null : index.get(p);
            boolean l = at != null && reader.hasChild.test(live.get(at), vehicle[i]);
            String wrong = !Objects.equals(p, parent[i]) ? "parent " + p + " read as " + parent[i]
                    : reader.acting.test(c) != acting[i] ? "command"
                    : reader.suspended.test(c) != suspended[i] ? "suspension at " + nowMillis
                    : l != listed[i] ? "listed by its parent: " + l
                    : !reader.holdsSeats.test(c, seats.get(i)) ? "seats " + reader.seats.apply(c) + " read as " + seats.get(i)
                    : null;
            if (wrong != null) {
                throw new IllegalStateException("the incremental readings of " + vehicle[i] + " are stale: " + wrong
                        + ": a writer of its links did not move its link version");
            }
        }
    }

    /**
     * Tells these readings that {@code cell}'s link version moved: the next {@link #read} reads it
     * again. A cell not among the live cells read last is read anyway when it first appears.
     */
    void moved(C cell) {
        Integer i = position.get(cell);
        if (i != null) {
            told[i] = true;
        }
    }

    /** Records that the structural rules held on the readings as they stand. */
    void passed() {
        passed = true;
    }

    /** Cells re-read so far because their version moved (or the live cells changed). */
    long reread() {
        return reread;
    }

    private boolean sameCells(List<C> now) {
        if (now == cells) {
            return true;   // the same list: callers pass lists they do not change
        }
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

    /** A new set of live cells: every reading starts empty, and every cell is read afresh. */
    private void adopt(List<C> now) {
        cells = now;
        live.clear();
        live.addAll(now);
        int n = now.size();
        index.clear();
        vehicle = new String[n];
        told = new boolean[n];
        position.clear();
        parent = new String[n];
        up = new int[n];
        acting = new boolean[n];
        suspended = new boolean[n];
        leaseUntil = new long[n];
        listed = new boolean[n];
        moved = new boolean[n];
        seats = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
            vehicle[i] = reader.vehicle.apply(now.get(i));
            position.put(now.get(i), i);
            index.put(vehicle[i], i);
            seats.add(List.of());
            up[i] = -1;
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
