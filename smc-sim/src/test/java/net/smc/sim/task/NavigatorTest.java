package net.smc.sim.task;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import net.smc.sim.hardware.Pose;
import net.smc.sim.map.OccupancyGrid;
import net.smc.sim.map.Zone;
import org.junit.jupiter.api.Test;

class NavigatorTest {

    @Test
    void goTo_reachesTheGoalAroundAnObstacleWithoutBumping() throws Exception {
        FakeWorld world = new FakeWorld(8, 6).box(3.5, 0, 4.0, 4.2);
        FakeRobot robot = world.robot("r1", 1, 2, 0);
        Navigator nav = new Navigator(robot, new OccupancyGrid(0, 0, 8, 6, 0.25));
        EventLog log = new EventLog().watch(nav);
        nav.start();
        nav.goTo(7, 2);
        assertTrue(world.runUntil(() -> !nav.isMoving(), 200), "navigator still moving");
        assertEquals(1, log.of("arrived").size(), "arrived events: " + log.lines);
        assertEquals(List.of(), log.of("blocked"));
        assertTrue(Math.hypot(robot.x - 7, robot.y - 2) < 0.25, "robot at " + robot.x + "," + robot.y);
        assertEquals(0, robot.bumps, "bumps");
        assertTrue(robot.trail.stream().anyMatch(p -> p.y() > 4.2), "the path went around the wall's end");
        log.assertNoErrors();
    }

    /**
     * A doorway two cells wide between struck cells is closed at the Explorer's clearance: the
     * navigator takes it with the body's half-width and 5 cm rather than give up.
     */
    @Test
    void goTo_throughADoorwayTooNarrowForTheClearance_takesItWithTheNarrowClearance() throws Exception {
        FakeWorld world = new FakeWorld(8, 6).box(3.5, 0, 4.0, 2.45).box(3.5, 3.05, 4.0, 6);
        FakeRobot robot = world.robot("r1", 1, 2.75, 0);
        OccupancyGrid map = new OccupancyGrid(0, 0, 8, 6, 0.25);
        for (int r = 0; r < map.rows(); r++) {   // the map as mapped: the wall in columns 14-15, rows 10-11 open
            for (int c = 0; c < map.cols(); c++) {
                var p = map.centre(c, r);
                boolean wall = (c == 14 || c == 15) && (r <= 9 || r >= 12);
                for (int i = 0; i < 3; i++) {
                    if (wall) {
                        map.markOccupied(p.x(), p.y());
                    } else {
                        map.markFree(p.x(), p.y());
                    }
                }
            }
        }
        assertTrue(new net.smc.sim.map.PathPlanner(Explorer.CLEARANCE).plan(map, new net.smc.sim.map.Point(1, 2.75),
                new net.smc.sim.map.Point(7, 2.75), List.of(), 0).isEmpty(), "no way at the full clearance");
        Navigator nav = new Navigator(robot, map, Explorer.CLEARANCE);
        EventLog log = new EventLog().watch(nav);
        nav.start();
        nav.goTo(7, 2.75);
        assertTrue(world.runUntil(() -> !nav.isMoving(), 200), "navigator still moving");
        assertEquals(List.of(), log.of("blocked"));
        assertEquals(1, log.of("arrived").size(), "arrived events: " + log.lines);
        assertTrue(robot.x > 6.7, "through the doorway: x " + robot.x);
        log.assertNoErrors();
    }

    /**
     * A path at the full clearance is kept while it stays open: a cheaper way that opens on the
     * map meanwhile (here a stretch of wall whose cells turn free, as rays ending short of a wall
     * on a grid line free them from afar) does not turn the robot round. Re-planning every second
     * whatever the path, it drove to that wall, and back when the ring marked it again.
     */
    @Test
    void goTo_keepsAPathThatStaysOpen_whenAWayThroughAWallOpensOnTheMap() throws Exception {
        FakeWorld world = new FakeWorld(10, 6).box(5, 0, 5.25, 4.5);   // a wall with a way round at its north end
        FakeRobot robot = world.robot("r1", 2, 1, 0);
        OccupancyGrid map = world.mapped(0.25);
        Navigator nav = new Navigator(robot, map, Explorer.CLEARANCE);
        EventLog log = new EventLog().watch(nav);
        nav.start();
        nav.goTo(8, 1);
        world.run(2);
        for (int r = map.row(0.5); r <= map.row(2); r++) {   // the wall's south stretch now looks free
            for (int i = 0; i < 8; i++) {
                map.markFree(5.125, map.centre(0, r).y());
            }
        }
        assertTrue(new net.smc.sim.map.PathPlanner(Explorer.CLEARANCE).plan(map, new net.smc.sim.map.Point(robot.x, robot.y),
                new net.smc.sim.map.Point(8, 1), List.of(), nav.margin()).orElseThrow().stream().allMatch(p -> p.y() < 3.5),
                "a straight way through the wall is open on the map");
        int from = robot.trail.size();
        assertTrue(world.runUntil(() -> !nav.isMoving(), 200), "navigator still moving");
        assertEquals(1, log.of("arrived").size(), "events: " + log.lines);
        double closest = robot.trail.subList(from, robot.trail.size()).stream()
                .mapToDouble(p -> Math.hypot(p.x() - 5.1, p.y() - 1.25)).min().orElseThrow();
        assertTrue(closest > 1.5, "kept to its way round the wall: came within " + closest + " m of the stretch that looked free");
    }

    @Test
    void goTo_neverEntersAnAvoidedZonePlusItsMargin() throws Exception {
        FakeWorld world = new FakeWorld(8, 6);
        FakeRobot robot = world.robot("r1", 1, 3, 0);
        Navigator nav = new Navigator(robot, new OccupancyGrid(0, 0, 8, 6, 0.25));
        EventLog log = new EventLog().watch(nav);
        log.cell.run("zone.p2", "root/task/Navigator avoid: 4 y: 3 radius: 1; margin: 0.5; goTo: 7 y: 3.");
        log.assertNoErrors();
        nav.start();
        assertTrue(world.runUntil(() -> !nav.isMoving(), 200));
        assertEquals(1, log.of("arrived").size(), "events: " + log.lines);
        double closest = robot.trail.stream().mapToDouble(p -> Math.hypot(p.x() - 4, p.y() - 3)).min().orElseThrow();
        assertTrue(closest >= 1.5, "came within " + closest + " m of the zone's centre");
    }

    @Test
    void goTo_aGoalInsideAnAvoidedZone_isBlocked() throws Exception {
        FakeWorld world = new FakeWorld(8, 6);
        FakeRobot robot = world.robot("r1", 1, 3, 0);
        Navigator nav = new Navigator(robot, new OccupancyGrid(0, 0, 8, 6, 0.25));
        EventLog log = new EventLog().watch(nav);
        nav.start();
        nav.avoid(5, 3, 1);
        nav.goTo(5.5, 3);
        world.run(1);
        assertEquals(1, log.of("blocked").size(), "events: " + log.lines);
        assertEquals(5.5, EventLog.num(log.of("blocked").get(0)[0]));
        assertFalse(nav.isMoving());
        assertTrue(robot.x < 1.1, "the robot stayed put");
    }

    @Test
    void goTo_offTheMap_failsNamingTheGoalAndTheMap() {
        FakeWorld world = new FakeWorld(8, 6);
        Navigator nav = new Navigator(world.robot("r1", 1, 3, 0), new OccupancyGrid(0, 0, 8, 6, 0.25));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> nav.goTo(9, 3));
        assertTrue(e.getMessage().contains("(9.0, 3.0) is off the map"), e.getMessage());
    }

    @Test
    void avoid_aNonPositiveRadius_isRefused() {
        Navigator nav = new Navigator(new FakeWorld(8, 6).robot("r1", 1, 3, 0), new OccupancyGrid(0, 0, 8, 6, 0.25));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> nav.avoid(1, 1, 0));
        assertTrue(e.getMessage().contains("zone radius 0.0 must be a positive"), e.getMessage());
    }

    @Test
    void startAndStop_registerAndRemoveTheControlLoop_andStopTheRobot() {
        FakeWorld world = new FakeWorld(8, 6);
        FakeRobot robot = world.robot("r1", 1, 3, 0);
        Navigator nav = new Navigator(robot, new OccupancyGrid(0, 0, 8, 6, 0.25));
        nav.start();
        assertEquals(1, robot.loopCount());
        nav.goTo(7, 3);
        world.run(2);
        assertTrue(robot.speed() > 0.1);
        nav.stop();
        assertEquals(0, robot.loopCount());
        world.run(1);
        assertEquals(0, robot.speed(), 1e-9);
    }

    @Test
    void handover_carriesGoalZonesAndMargin() {
        FakeWorld world = new FakeWorld(8, 6);
        Navigator a = new Navigator(world.robot("a", 1, 3, 0), new OccupancyGrid(0, 0, 8, 6, 0.25));
        a.avoid(4, 3, 1);
        a.margin(0.7);
        a.goTo(7, 3);
        Map<String, Object> state = a.exportState();
        Navigator b = new Navigator(world.robot("b", 1, 1, 0), new OccupancyGrid(0, 0, 8, 6, 0.25));
        b.importState(state);
        assertEquals(List.of(new Zone(4, 3, 1)), b.zones());
        assertEquals(0.7, b.margin());
        assertEquals(7.0, b.goal().orElseThrow().x());
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> b.importState(Map.of("zones", List.of(List.of(1, 2)))));
        assertTrue(e.getMessage().contains("each of 'zones' must be [x, y, radius]"), e.getMessage());
    }

    static double distance(Pose p, double x, double y) {
        return Math.hypot(p.x() - x, p.y() - y);
    }
}
