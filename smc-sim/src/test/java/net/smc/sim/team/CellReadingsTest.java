package net.smc.sim.team;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.function.Consumer;

import net.smc.core.cell.Seat;
import org.junit.jupiter.api.Test;

/**
 * The readings the invariant checks keep between checks: a check may skip the structural rules only
 * when every cell reads exactly as at the last check that passed them; a change of any reading in
 * any cell (parent, command, lease, being listed by the parent, seats, which cells are live) makes
 * the next check walk them, and so does a walk that did not pass.
 */
class CellReadingsTest {
    /** A stand-in cell whose fields a test changes between checks. */
    private static final class Node {
        final String vehicle;
        String parent;
        boolean acting;
        boolean suspended;
        final Set<String> children = new HashSet<>();
        List<Seat> seats = new ArrayList<>();

        Node(String vehicle, String parent, Seat... seats) {
            this.vehicle = vehicle;
            this.parent = parent;
            this.seats.addAll(List.of(seats));
        }
    }

    private static CellReadings<Node> readings() {
        return new CellReadings<>(n -> n.vehicle, n -> n.parent, n -> n.acting, n -> n.suspended,
                (n, v) -> n.children.contains(v), n -> List.copyOf(n.seats), (n, s) -> n.seats.equals(s));
    }

    private List<Node> team() {
        Node cdr = new Node("cdr", null, new Seat("commander", 0));
        cdr.acting = true;
        Node a = new Node("a", "cdr", new Seat("surveyor", 0));
        Node b = new Node("b", "a", new Seat("detector", 0));
        cdr.children.add("a");
        a.children.add("b");
        return List.of(cdr, a, b);
    }

    /** Reads, records a passed walk, and checks that an unchanged team needs no walk. */
    private static void settle(CellReadings<Node> r, List<Node> cells) {
        assertTrue(r.read(cells), "a new reading needs a walk");
        r.passed();
        assertFalse(r.read(cells), "nothing changed since a passed walk");
    }

    private void assertChangeIsSeen(String what, Consumer<List<Node>> change) {
        List<Node> cells = team();
        CellReadings<Node> r = readings();
        settle(r, cells);
        change.accept(cells);
        assertTrue(r.read(cells), what + " must make the next check walk the rules");
        r.passed();
        assertFalse(r.read(cells), what + ": read again after a passed walk, nothing new");
    }

    @Test
    void everyKindOfChangeInAnyCellIsSeen() {
        assertChangeIsSeen("a new parent", c -> c.get(2).parent = "cdr");
        assertChangeIsSeen("losing the parent", c -> c.get(1).parent = null);
        assertChangeIsSeen("taking command", c -> c.get(1).acting = true);
        assertChangeIsSeen("a lease running out", c -> c.get(2).suspended = true);
        assertChangeIsSeen("a parent dropping its child", c -> c.get(1).children.remove("b"));
        assertChangeIsSeen("a seat more", c -> c.get(2).seats.add(new Seat("surveyor", 0)));
        assertChangeIsSeen("another slot of the same role", c -> c.get(2).seats.set(0, new Seat("detector", 1)));
        assertChangeIsSeen("no seat", c -> c.get(1).seats.clear());
    }

    @Test
    void aParentListingAChildItDidNotIsSeen() {
        List<Node> cells = team();
        cells.get(1).children.remove("b");
        CellReadings<Node> r = readings();
        settle(r, cells);
        cells.get(0).children.add("b");   // not b's parent: nothing the rules read
        assertFalse(r.read(cells));
        cells.get(1).children.add("b");
        assertTrue(r.read(cells), "b's parent lists it now");
    }

    @Test
    void aChangeOfTheLiveCellsIsSeen() {
        List<Node> cells = team();
        CellReadings<Node> r = readings();
        settle(r, cells);
        assertTrue(r.read(List.of(cells.get(0), cells.get(1))), "a cell gone");
        r.passed();
        assertTrue(r.read(cells), "a cell back");
        r.passed();
        List<Node> restarted = List.of(cells.get(0), cells.get(1), new Node("b", "a", new Seat("detector", 0)));
        assertTrue(r.read(restarted), "a cell replaced by a fresh one of the same vehicle");
    }

    @Test
    void aWalkThatDidNotPassIsWalkedAgain() {
        List<Node> cells = team();
        CellReadings<Node> r = readings();
        assertTrue(r.read(cells));
        // No passed(): the walk found a violation (and threw); whoever goes on checks again.
        assertTrue(r.read(cells), "readings no walk has passed on are never trusted");
    }

    @Test
    void theReadingsAreWhatTheCellsSay() {
        List<Node> cells = new ArrayList<>(team());
        cells.add(new Node("d", "gone", new Seat("detector", 1)));   // its parent is not live
        cells.get(2).suspended = true;
        CellReadings<Node> r = readings();
        r.read(cells);
        assertEquals(4, r.size());
        assertTrue(r.acting(0));
        assertNull(r.parent(0));
        assertFalse(r.listedByParent(0));
        assertTrue(r.listedByParent(1));
        assertTrue(r.listedByParent(2));
        assertTrue(r.suspended(2));
        assertEquals("gone", r.parent(3));
        assertFalse(r.listedByParent(3));
        assertEquals(List.of(cells.get(0)), r.commanders());
    }
}
