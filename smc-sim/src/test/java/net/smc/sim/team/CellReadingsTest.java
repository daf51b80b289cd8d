package net.smc.sim.team;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.function.Function;

import net.smc.core.cell.Seat;
import org.junit.jupiter.api.Test;

/**
 * The readings the invariant checks keep between checks, driven by the cells' changes: a check
 * re-reads a cell when told it moved (and whether it is listed when it or its parent moved), and
 * a cell whose lease ran out with time alone; it may skip the structural rules only when every
 * reading is as at the last check that passed them. Every test here runs with the full read that
 * verifies the incremental one on, and one shows that a change made without moving the version is
 * caught by it.
 */
class CellReadingsTest {
    /** The stand-in cells' clock. */
    private long now;

    /** A stand-in cell whose fields a test changes between checks (telling the readings it moved, as a cell's link listener does). */
    private final class Node {
        final String vehicle;
        long leaseUntil = Long.MAX_VALUE;
        String parent;
        boolean acting;
        final Set<String> children = new HashSet<>();
        List<Seat> seats = new ArrayList<>();

        Node(String vehicle, String parent, Seat... seats) {
            this.vehicle = vehicle;
            this.parent = parent;
            this.seats.addAll(List.of(seats));
        }

        boolean suspended() {
            return parent != null && !acting && now > leaseUntil;
        }
    }

    private CellReadings<Node> readings() {
        return new CellReadings<>(new CellReadings.Reader<Node>(n -> n.vehicle, n -> n.parent,
                n -> n.acting, Node::suspended, n -> n.leaseUntil, (n, v) -> n.children.contains(v),
                n -> List.copyOf(n.seats), (n, s) -> n.seats.equals(s))).verifying(true);
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
    private void settle(CellReadings<Node> r, List<Node> cells) {
        assertTrue(r.read(cells, now), "a new reading needs a walk");
        r.passed();
        assertFalse(r.read(cells, now), "nothing changed since a passed walk");
    }

    /** {@code change} changes one cell and returns it; the readings are told it moved. */
    private void assertChangeIsSeen(String what, Function<List<Node>, Node> change) {
        List<Node> cells = team();
        CellReadings<Node> r = readings();
        settle(r, cells);
        r.moved(change.apply(cells));
        assertTrue(r.read(cells, now), what + " must make the next check walk the rules");
        r.passed();
        assertFalse(r.read(cells, now), what + ": read again after a passed walk, nothing new");
    }

    @Test
    void everyKindOfChangeInAnyCellIsSeen() {
        assertChangeIsSeen("a new parent", c -> set(c.get(2), n -> n.parent = "cdr"));
        assertChangeIsSeen("losing the parent", c -> set(c.get(1), n -> n.parent = null));
        assertChangeIsSeen("taking command", c -> set(c.get(1), n -> n.acting = true));
        assertChangeIsSeen("a lease cut short", c -> set(c.get(2), n -> n.leaseUntil = now - 1));
        assertChangeIsSeen("a parent dropping its child", c -> set(c.get(1), n -> n.children.remove("b")));
        assertChangeIsSeen("a seat more", c -> set(c.get(2), n -> n.seats.add(new Seat("surveyor", 0))));
        assertChangeIsSeen("another slot of the same role", c -> set(c.get(2), n -> n.seats.set(0, new Seat("detector", 1))));
        assertChangeIsSeen("no seat", c -> set(c.get(1), n -> n.seats.clear()));
    }

    private static Node set(Node n, java.util.function.Consumer<Node> change) {
        change.accept(n);
        return n;
    }

    @Test
    void aLeaseRunningOutWithTimeAlone_orRenewedWithoutAVersion_isSeen() {
        List<Node> cells = team();
        cells.get(2).leaseUntil = 1_000;
        now = 500;
        CellReadings<Node> r = readings();
        settle(r, cells);
        cells.get(2).leaseUntil = 1_200;   // renewed before it ran out: no version moves
        now = 1_100;
        assertFalse(r.read(cells, now), "the lease read ran out, but it was renewed: nothing changed");
        now = 1_201;
        assertTrue(r.read(cells, now), "no version moved, but b's lease ran out");
        assertTrue(r.suspended(2));
        r.passed();
        assertFalse(r.read(cells, now));
        cells.get(2).leaseUntil = 3_000;   // renewed after it lapsed: still no version
        assertTrue(r.read(cells, now), "b's lease was renewed");
        assertFalse(r.suspended(2));
    }

    @Test
    void aParentListingAChildItDidNotIsSeen() {
        List<Node> cells = team();
        cells.get(1).children.remove("b");
        CellReadings<Node> r = readings();
        settle(r, cells);
        cells.get(0).children.add("b");   // not b's parent: nothing the rules read
        r.moved(cells.get(0));
        assertFalse(r.read(cells, now));
        cells.get(1).children.add("b");
        r.moved(cells.get(1));
        assertTrue(r.read(cells, now), "b's parent lists it now");
        assertTrue(r.listedByParent(2));
    }

    @Test
    void aChangeThatDoesNotMoveTheVersionIsCaughtByTheVerifyingRead() {
        List<Node> cells = team();
        CellReadings<Node> r = readings();
        settle(r, cells);
        cells.get(2).seats.add(new Seat("surveyor", 1));   // version not moved: a writer that forgot
        IllegalStateException e = assertThrows(IllegalStateException.class, () -> r.read(cells, now));
        assertTrue(e.getMessage().contains("incremental readings of b are stale: seats"), e.getMessage());
    }

    @Test
    void aChangeOfTheLiveCellsIsSeen() {
        List<Node> cells = team();
        CellReadings<Node> r = readings();
        settle(r, cells);
        assertTrue(r.read(List.of(cells.get(0), cells.get(1)), now), "a cell gone");
        r.passed();
        assertTrue(r.read(cells, now), "a cell back");
        r.passed();
        List<Node> restarted = List.of(cells.get(0), cells.get(1), new Node("b", "a", new Seat("detector", 0)));
        assertTrue(r.read(restarted, now), "a cell replaced by a fresh one of the same vehicle");
    }

    @Test
    void aWalkThatDidNotPassIsWalkedAgain() {
        List<Node> cells = team();
        CellReadings<Node> r = readings();
        assertTrue(r.read(cells, now));
        // No passed(): the walk found a violation (and threw); whoever goes on checks again.
        assertTrue(r.read(cells, now), "readings no walk has passed on are never trusted");
    }

    @Test
    void theReadingsAreWhatTheCellsSay() {
        List<Node> cells = new ArrayList<>(team());
        cells.add(new Node("d", "gone", new Seat("detector", 1)));   // its parent is not live
        cells.get(2).leaseUntil = now - 1;
        CellReadings<Node> r = readings();
        r.read(cells, now);
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
