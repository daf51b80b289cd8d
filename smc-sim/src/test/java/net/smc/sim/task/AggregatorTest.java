package net.smc.sim.task;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import net.smc.sim.map.OccupancyGrid;
import org.junit.jupiter.api.Test;

class AggregatorTest {

    private final FakeRobot robot = new FakeWorld(4, 4).robot("agg", 1, 1, 0);

    @Test
    void merge_twoHalfMaps_giveTheWholeMapWithBothObstacles() {
        OccupancyGrid left = new OccupancyGrid(0, 0, 4, 4, 0.5);
        OccupancyGrid right = new OccupancyGrid(0, 0, 4, 4, 0.5);
        for (double y = 0.25; y < 4; y += 0.5) {
            left.observeRay(0.1, y, 1.9, y, false);
            right.observeRay(3.9, y, 2.1, y, false);
        }
        left.markOccupied(0.25, 0.25);
        right.markOccupied(3.75, 3.75);
        Aggregator aggregator = new Aggregator(robot, new OccupancyGrid(0, 0, 4, 4, 0.5));
        aggregator.merge(left);
        assertEquals(0.5, aggregator.exploredFraction(), 1e-9);
        aggregator.merge(right);
        assertEquals(1.0, aggregator.exploredFraction(), 1e-9);
        assertTrue(aggregator.map().isOccupied(0, 0));
        assertTrue(aggregator.map().isOccupied(7, 7));
        assertTrue(aggregator.map().isFree(3, 3));
    }

    @Test
    void merge_aGridOfAnotherGeometry_isRefused() {
        Aggregator aggregator = new Aggregator(robot, new OccupancyGrid(0, 0, 4, 4, 0.5));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> aggregator.merge(new OccupancyGrid(0, 0, 4, 4, 0.25)));
        assertTrue(e.getMessage().contains("must have the same origin, resolution and size"), e.getMessage());
    }

    @Test
    void report_nearbyReportsOfOneKindAreOneHazard_andEachNewHazardIsAnnounced() throws Exception {
        Aggregator aggregator = new Aggregator(robot, new OccupancyGrid(0, 0, 4, 4, 0.5));
        EventLog log = new EventLog().watch(aggregator);
        aggregator.start();
        log.cell.run("reports.p2", """
                a := root/task/Aggregator.
                a report: "chemical" x: 1 y: 1.
                a report: "chemical" x: 1.3 y: 1.
                a report: "radiation" x: 1.1 y: 1.
                a report: "chemical" x: 3 y: 3.
                root print: "count|" + a hazards size.
                """);
        log.assertNoErrors();
        List<List<Object>> hazards = aggregator.hazards();
        assertEquals(3, hazards.size());
        assertEquals("chemical", hazards.get(0).get(0));
        assertEquals(1.15, (Double) hazards.get(0).get(1), 1e-9);
        assertEquals(2, hazards.get(0).get(3));
        assertEquals(3, log.of("hazardAdded").size());
        assertEquals("3", log.of("count").get(0)[0]);
    }

    @Test
    void handover_carriesHazardsAndTheMap() {
        Aggregator a = new Aggregator(robot, new OccupancyGrid(0, 0, 4, 4, 0.5));
        a.report("chemical", 1, 1);
        a.report("chemical", 1.2, 1);
        a.map().markOccupied(2, 2);
        Aggregator b = new Aggregator(robot, new OccupancyGrid(0, 0, 4, 4, 0.5));
        b.importState(a.exportState());
        assertEquals(a.hazards(), b.hazards());
        assertEquals(1, b.map().knownCells());
    }
}
