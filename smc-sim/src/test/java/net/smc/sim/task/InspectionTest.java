package net.smc.sim.task;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import net.smc.core.transport.sim.SimulationScheduler;
import net.smc.sim.map.OccupancyGrid;
import net.smc.sim.robot.KoalaSpec;
import net.smc.sim.robot.SimRobot;
import net.smc.sim.world.SimWorld;
import net.smc.sim.world.Worlds;
import org.junit.jupiter.api.Test;

/**
 * The reconnaissance's task additions in a real world: a detector inspects a suspected hazard and
 * confirms it from outside its radius of effect; the Explorer keeps out of an avoided zone; maps
 * travel as rows and fill only what the receiver does not know.
 */
class InspectionTest {
    private static final String HAZARD = "<hazard id='h1' kind='chemical' x='6' y='4' radius='0.15' effect='0.6' disables='true'/>"
            + "<start id='s' x='1' y='4' heading='0'/>";

    /** A detector robot d1 at the arena's start, its task started with a threshold of 0.35 and its events logged. */
    private record Rig(SimulationScheduler scheduler, SimWorld world, SimRobot robot, HazardDetector detector, EventLog log) {

        /**
         * Runs the world in steps of 100 ms, at most {@code steps}, until the detector has no
         * inspection left, and checks that it ended and that the robot kept out of the hazard at
         * (6, 4), whose effect disables within 0.6 m.
         */
        void runUntilInspected(int steps) {
            double closest = Double.POSITIVE_INFINITY;
            for (int s = 0; s < steps && detector.isInspecting(); s++) {
                scheduler.runFor(100);
                closest = Math.min(closest, Math.hypot(robot.x() - 6, robot.y() - 4));
            }
            assertFalse(detector.isInspecting(), "the inspections ended");
            assertFalse(robot.disabled(), "the detector stayed out of the hazard's reach: " + robot.disabledBy());
            assertTrue(closest > 0.6, "closest approach " + closest + " m; the hazard disables within 0.6 m");
        }
    }

    private static Rig detectorRig() throws Exception {
        SimulationScheduler scheduler = new SimulationScheduler();
        SimWorld world = SimWorld.builder(Worlds.arena(12, 8, HAZARD), scheduler).seed(4).build();
        SimRobot robot = world.addRobot("d1", "s");
        HazardDetector detector = new HazardDetector(robot, new OccupancyGrid(0, 0, 12, 8, 0.25));
        EventLog log = new EventLog().watch(detector);
        detector.start();
        detector.threshold(0.35);
        return new Rig(scheduler, world, robot, detector, log);
    }

    @Test
    void aDetectorInspectsASuspectedHazard_confirmsItFromOutsideItsReach_andSaysSo() throws Exception {
        Rig rig = detectorRig();
        SimWorld world = rig.world();
        HazardDetector detector = rig.detector();
        EventLog log = rig.log();
        detector.inspect(6, 4);
        detector.inspect(6.5, 4.2);   // within a metre of the queued point: the same suspect
        assertTrue(detector.isInspecting());
        world.start();
        rig.runUntilInspected(600);
        assertEquals(1, detector.hazards().size(), "confirmed once: " + detector.hazards());
        assertTrue(log.lines.stream().anyMatch(l -> l.startsWith("hazardDetected|hazardDetected|d1|chemical|")), log.lines.toString());
        assertTrue(log.lines.stream().anyMatch(l -> l.startsWith("inspected|6.0|4.0|true")), log.lines.toString());
        assertEquals(1, log.lines.stream().filter(l -> l.startsWith("inspected|")).count(), "one inspection: " + log.lines);
    }

    @Test
    void aDetectorThatFindsNothingWhereItWasSent_looksFromTheOtherSides_untilItSensesTheHazard() throws Exception {
        Rig rig = detectorRig();
        SimWorld world = rig.world();
        HazardDetector detector = rig.detector();
        EventLog log = rig.log();
        // the suspect as a poor camera estimate puts it: 1.6 m north of the hazard; seen from the
        // robot's side (west) the sensor stays below the threshold, from the south it does not
        detector.inspect(6, 5.6);
        world.start();
        rig.runUntilInspected(1200);
        assertEquals(1, detector.hazards().size(), "found from another side: " + log.lines);
        assertEquals(List.of("inspected|6.0|5.6|true"), log.lines.stream().filter(l -> l.startsWith("inspected|")).toList());
    }

    /**
     * The sensor gives no bearing: a hazard first sensed on the way to a suspect farther off is the
     * nearby suspect's, not the one being inspected. The inspection under way goes on (and here
     * finds nothing, since nothing is there), the detector keeps out of the hazard it sensed, and
     * the nearby suspect is done with. Before, the inspection under way ended as confirmed and the
     * zone kept round the confirmed hazard was drawn round the far point, which no later try could
     * then reach.
     */
    @Test
    void aHazardSensedOnTheWayToAnotherSuspect_isTheNearSuspects_andTheInspectionGoesOn() throws Exception {
        Rig rig = detectorRig();
        SimulationScheduler scheduler = rig.scheduler();
        SimWorld world = rig.world();
        SimRobot robot = rig.robot();
        HazardDetector detector = rig.detector();
        EventLog log = rig.log();
        detector.inspect(10, 4);   // beyond the hazard (6, 4), on the robot's line
        world.start();
        scheduler.runFor(500);
        detector.inspect(6, 4);    // queued while the far point is being inspected
        rig.runUntilInspected(3000);
        assertEquals(1, detector.hazards().size(), "the hazard passed on the way was confirmed: " + log.lines);
        assertTrue(robot.x() > 8, "the detector went on to the far point: at " + robot.x() + ", " + robot.y());
        assertEquals(List.of("inspected|10.0|4.0|false"), log.lines.stream().filter(l -> l.startsWith("inspected|")).toList(),
                "the far point was looked at from every side, and the near suspect not inspected again");
        assertTrue(detector.navigator().zones().stream().allMatch(z -> Math.hypot(z.x() - 6, z.y() - 4) < 1e-9),
                "the zone kept is round the hazard sensed, not the far point: " + detector.navigator().zones());
    }

    @Test
    void aDetectorSentWhereNothingIs_looksFromEverySide_thenSaysNothingIsThere() throws Exception {
        Rig rig = detectorRig();
        SimulationScheduler scheduler = rig.scheduler();
        SimWorld world = rig.world();
        SimRobot robot = rig.robot();
        HazardDetector detector = rig.detector();
        EventLog log = rig.log();
        detector.inspect(3, 2);
        world.start();
        // the first side faces the robot (north-west of the point); the others are a quarter turn apart
        java.util.Set<Integer> sides = new java.util.TreeSet<>();
        for (int s = 0; s < 2400 && detector.isInspecting(); s++) {
            scheduler.runFor(100);
            for (int k = 0; k < 4; k++) {
                double a = Math.toRadians(135 + 90 * k);
                if (Math.hypot(robot.x() - 3 - 0.8 * Math.cos(a), robot.y() - 2 - 0.8 * Math.sin(a)) < 0.4) {
                    sides.add(k);
                }
            }
        }
        assertFalse(detector.isInspecting(), "the inspection ended");
        assertEquals(java.util.Set.of(0, 1, 2, 3), sides, "looked from the four sides");
        assertEquals(List.of("inspected|3.0|2.0|false"), log.lines.stream().filter(l -> l.startsWith("inspected|")).toList());
        assertTrue(detector.hazards().isEmpty());
    }

    @Test
    void theExplorerKeepsOutOfAnAvoidedZone() {
        SimulationScheduler scheduler = new SimulationScheduler();
        SimWorld world = SimWorld.builder(Worlds.arena(12, 8, "<start id='s' x='1' y='4' heading='0'/>"), scheduler).seed(5)
                .robotSpec(KoalaSpec.koala().withIrRange(1.0)).build();
        SimRobot robot = world.addRobot("s1", "s");
        Explorer explorer = new Explorer(robot, new OccupancyGrid(0, 0, 12, 8, 0.25));
        explorer.start();
        explorer.avoid(6, 4, 1.5);
        explorer.explore();
        world.start();
        double closest = Double.POSITIVE_INFINITY;
        for (int s = 0; s < 1200; s++) {
            scheduler.runFor(100);
            closest = Math.min(closest, Math.hypot(robot.x() - 6, robot.y() - 4));
        }
        assertTrue(explorer.exploredFraction() > 0.5, "it explored: " + explorer.exploredFraction());
        assertTrue(closest > 1.5, "it kept out of the zone: closest " + closest + " m");
    }

    @Test
    void mapsTravelAsRows_theAggregatorMergesThem_andADetectorFillsOnlyWhatItDoesNotKnow() {
        OccupancyGrid surveyor = new OccupancyGrid(0, 0, 4, 2, 0.5);
        surveyor.markFree(0.2, 0.2);
        surveyor.markOccupied(1.2, 0.2);
        surveyor.markOccupied(1.2, 0.2);
        surveyor.markOccupied(2.2, 0.2);
        @SuppressWarnings("unchecked")
        List<Object> rows = (List<Object>) (List<?>) surveyor.toState().get("cells");
        SimWorld world = Worlds.world(Worlds.arena(4, 2, "<start id='s' x='1' y='1' heading='0'/>"), 1);
        SimRobot robot = world.addRobot("r", "s");
        Aggregator aggregator = new Aggregator(robot, new OccupancyGrid(0, 0, 4, 2, 0.5));
        aggregator.merge(() -> rows);
        assertEquals(3, aggregator.map().knownCells());
        assertTrue(aggregator.map().isOccupied(2, 0));
        OccupancyGrid own = new OccupancyGrid(0, 0, 4, 2, 0.5);
        own.markFree(2.2, 0.2);
        own.markFree(2.2, 0.2);
        HazardDetector detector = new HazardDetector(robot, own);
        detector.merge(() -> rows);
        assertTrue(own.isFree(4, 0), "its own view of a cell stands");
        assertTrue(own.isOccupied(2, 0) && own.isFree(0, 0), "unknown cells are filled from the other's map");
    }
}
