package net.smc.sim.map;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

class OccupancyGridTest {

    @Test
    void observeRay_freesTheCellsCrossed_andMarksTheHit() {
        OccupancyGrid g = new OccupancyGrid(0, 0, 4, 1, 0.5);
        g.observeRay(0.25, 0.25, 2.25, 0.25, true);
        assertTrue(g.isFree(0, 0) && g.isFree(3, 0));
        assertTrue(g.isOccupied(4, 0));
        assertFalse(g.isKnown(5, 0));
        assertEquals(5.0 / 16, g.exploredFraction(), 1e-9);
    }

    @Test
    void oneMiss_doesNotEraseAHit() {
        OccupancyGrid g = new OccupancyGrid(0, 0, 4, 1, 0.5);
        g.markOccupied(1.25, 0.25);
        g.markFree(1.25, 0.25);
        assertTrue(g.isOccupied(2, 0));
    }

    @Test
    void state_roundTrips_andAMalformedCellIsNamed() {
        OccupancyGrid g = new OccupancyGrid(0, 0, 2, 1, 0.5);
        g.observeRay(0.25, 0.25, 1.25, 0.25, true);
        Map<String, Object> state = g.toState();
        assertEquals(List.of("..#?", "????"), state.get("cells"));
        assertEquals(state, OccupancyGrid.fromState(state).toState());
        Map<String, Object> bad = new java.util.HashMap<>(state);
        bad.put("cells", List.of("..x?", "????"));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> OccupancyGrid.fromState(bad));
        assertTrue(e.getMessage().contains("row 0, column 2 holds 'x'"), e.getMessage());
    }

    /**
     * The state's rows are kept between calls while no cell changes between unknown, free and
     * occupied: after every kind of change they are those of the cells as they are.
     */
    @Test
    void state_showsTheCellsAsTheyAre_afterEveryKindOfChange() {
        java.util.Random random = new java.util.Random(5);
        OccupancyGrid g = new OccupancyGrid(0, 0, 3, 2, 0.25);
        for (int i = 0; i < 2_000; i++) {
            double x = random.nextDouble() * 3;
            double y = random.nextDouble() * 2;
            switch (random.nextInt(6)) {
                case 0 -> g.markFree(x, y);
                case 1 -> g.markOccupied(x, y);
                case 2 -> g.observeRay(x, y, random.nextDouble() * 3, random.nextDouble() * 2, random.nextBoolean());
                case 3 -> {
                    OccupancyGrid other = new OccupancyGrid(0, 0, 3, 2, 0.25);
                    other.markOccupied(x, y);
                    other.markFree(random.nextDouble() * 3, random.nextDouble() * 2);
                    if (random.nextBoolean()) {
                        g.merge(other);
                    } else {
                        g.fillUnknown(other);
                    }
                }
                default -> { }   // no change: the kept rows serve
            }
            List<String> cells = new java.util.ArrayList<>();
            for (int r = 0; r < g.rows(); r++) {
                StringBuilder line = new StringBuilder();
                for (int c = 0; c < g.cols(); c++) {
                    line.append(g.isOccupied(c, r) ? '#' : g.isFree(c, r) ? '.' : '?');
                }
                cells.add(line.toString());
            }
            assertEquals(cells, g.toState().get("cells"), "after change " + i);
        }
    }

    @Test
    void constructor_refusesANonPositiveResolution() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new OccupancyGrid(0, 0, 2, 2, 0));
        assertTrue(e.getMessage().contains("resolution 0.0 must be a positive"), e.getMessage());
    }

    @Test
    void planner_goesAroundAWall_andKeepsOutOfAZonePlusMargin() {
        OccupancyGrid g = new OccupancyGrid(0, 0, 5, 5, 0.25);
        for (double y = 0; y < 3.5; y += 0.25) {
            g.markOccupied(2.6, y);
        }
        PathPlanner planner = new PathPlanner(0.2);
        List<Point> path = planner.plan(g, new Point(1, 1), new Point(4, 1), List.of(), 0).orElseThrow();
        assertEquals(new Point(4, 1), path.get(path.size() - 1));
        assertTrue(path.stream().anyMatch(p -> p.y() > 3.5), "around the wall's end: " + path);
        Zone zone = new Zone(2.5, 4.2, 0.3);
        assertTrue(planner.plan(g, new Point(1, 1), new Point(4, 1), List.of(zone), 0.5).isEmpty(),
                "the zone closes the only gap");
        assertTrue(planner.plan(g, new Point(1, 1), new Point(2.5, 4.3), List.of(zone), 0).isEmpty(), "goal in the zone");
    }

    /**
     * A robot standing deep inside a zone it is to avoid (it was inspecting the hazard when the zone
     * was set) has a way out: across the zone's closed cells to the nearest open one, then on; an
     * occupied cell is never crossed, and a goal inside the zone is still refused.
     */
    @Test
    void planner_leavesTheClosedRegionTheRobotStandsIn_butNeverCrossesAnOccupiedCell() {
        OccupancyGrid g = new OccupancyGrid(0, 0, 6, 6, 0.25);
        for (int r = 0; r < g.rows(); r++) {
            for (int c = 0; c < g.cols(); c++) {
                var p = g.centre(c, r);
                g.markFree(p.x(), p.y());
            }
        }
        Zone zone = new Zone(3, 3, 1.2);
        PathPlanner planner = new PathPlanner(0.3);
        Point inside = new Point(3.1, 2.6);
        assertTrue(planner.closedCells(g, List.of(zone), 0)[g.col(inside.x()) + 1 + g.row(inside.y()) * g.cols()],
                "the cells around the robot are closed");
        List<Point> path = planner.plan(g, inside, new Point(5.5, 5.5), List.of(zone), 0).orElseThrow();
        assertEquals(new Point(5.5, 5.5), path.get(path.size() - 1));
        for (int c = 10; c <= 13; c++) {   // a wall of occupied cells across the zone's east half
            for (int r = 0; r < g.rows(); r++) {
                var p = g.centre(c, r);
                g.markOccupied(p.x(), p.y());
                g.markOccupied(p.x(), p.y());
            }
        }
        assertTrue(planner.plan(g, new Point(2.4, 3), new Point(5.5, 5.5), List.of(zone), 0).isEmpty(),
                "no way out crosses an occupied cell");
        assertTrue(planner.plan(g, new Point(2.4, 3), new Point(0.5, 0.5), List.of(zone), 0).isPresent(),
                "out of the zone to the west");
        assertTrue(planner.plan(g, new Point(0.5, 0.5), new Point(2.2, 3.3), List.of(zone), 0).isEmpty(), "goal in the zone");
    }
}
