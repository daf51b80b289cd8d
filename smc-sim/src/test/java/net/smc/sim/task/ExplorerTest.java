package net.smc.sim.task;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import net.smc.sim.hardware.RobotHardware;
import net.smc.sim.map.OccupancyGrid;
import org.junit.jupiter.api.Test;

class ExplorerTest {

    @Test
    void explore_growsTheMapAndRaisesAreaExploredUntilDone() throws Exception {
        FakeWorld world = new FakeWorld(5, 5).box(2, 2, 3, 3);
        FakeRobot robot = world.robot("r1", 0.6, 0.6, 0);
        OccupancyGrid map = new OccupancyGrid(0, 0, 5, 5, 0.25);
        Explorer explorer = new Explorer(robot, map);
        EventLog log = new EventLog().watch(explorer);
        explorer.start();
        world.step(0.05);
        double first = map.exploredFraction();
        explorer.explore();
        assertTrue(world.runUntil(() -> !explorer.isExploring(), 600), "still exploring at " + map.exploredFraction());
        assertTrue(map.exploredFraction() > 0.9 && map.exploredFraction() > first,
                "explored " + first + " -> " + map.exploredFraction());
        List<String[]> reports = log.of("areaExplored");
        assertTrue(reports.size() >= 5, "areaExplored events: " + reports.size());
        assertEquals("true", reports.get(reports.size() - 1)[1], "the last report says exploring is done");
        assertFalse(log.of("obstacle").isEmpty());
        int nearBox = 0;
        int stray = 0;
        FakeWorld.Box box = world.boxes.get(0);
        for (int r = 0; r < map.rows(); r++) {
            for (int c = 0; c < map.cols(); c++) {
                var p = map.centre(c, r);
                boolean nearWall = p.x() < 0.4 || p.y() < 0.4 || p.x() > 4.6 || p.y() > 4.6;
                if (map.isOccupied(c, r) && box.near(p.x(), p.y(), 0.3)) {
                    nearBox++;
                } else if (map.isOccupied(c, r) && !nearWall && !box.near(p.x(), p.y(), 0.4)) {
                    stray++;
                }
            }
        }
        assertTrue(nearBox >= 8, "cells of the box on the map: " + nearBox);
        assertEquals(0, stray, "occupied cells away from every obstacle");
        log.assertNoErrors();
    }

    @Test
    void camera_raisesTargetSightedOncePerTagAtItsPosition() throws Exception {
        FakeWorld world = new FakeWorld(6, 5).thing("soldier", "soldier", 3, 2.5);
        FakeRobot robot = world.robot("r1", 1, 2.5, 0);
        Explorer explorer = new Explorer(robot, new OccupancyGrid(0, 0, 6, 5, 0.25));
        EventLog log = new EventLog().watch(explorer);
        explorer.start();
        world.run(1);
        List<String[]> seen = log.of("targetSighted");
        assertEquals(1, seen.size());
        assertEquals("soldier", seen.get(0)[0]);
        assertEquals(3.0, EventLog.num(seen.get(0)[2]), 1e-9);
        assertEquals(2.5, EventLog.num(seen.get(0)[3]), 1e-9);
    }

    @Test
    void handover_givesTheReplacementTheMapAndTheLastPosition() {
        FakeWorld world = new FakeWorld(5, 5);
        Explorer failed = new Explorer(world.robot("s1", 1, 1, 0), new OccupancyGrid(0, 0, 5, 5, 0.25));
        failed.start();
        world.run(0.5);
        var state = failed.exportState();
        assertEquals(1.0, (Double) state.get("x"), 1e-9);
        OccupancyGrid replacementMap = new OccupancyGrid(0, 0, 5, 5, 0.25);
        Explorer replacement = new Explorer(world.robot("s2", 4, 4, 0), replacementMap);
        replacement.importState(state);
        assertEquals(failed.map().knownCells(), replacementMap.knownCells());
        assertTrue(replacementMap.knownCells() > 0);
    }

    /**
     * The map as a robot standing west of a doorway may hold it: the west room (columns 0-15) known,
     * the wall in column 15 with a gap in rows 7-9, one cell known beyond the gap (column 16), and an
     * obstacle at (13, 7) whose ring, with the jambs', closes the way to the gap at the doorway
     * clearance. The only frontier worth driving to lies beyond the gap.
     */
    @Test
    void aFrontierOpenOnlyWithLessThanTheDoorwayClearance_isStillDrivenTo() {
        FakeWorld world = new FakeWorld(8, 4);
        FakeRobot robot = world.robot("r1", 1.125, 2.125, 0);
        OccupancyGrid map = new OccupancyGrid(0, 0, 8, 4, 0.25);
        for (int r = 0; r < map.rows(); r++) {
            for (int c = 0; c <= 16; c++) {
                var p = map.centre(c, r);
                boolean gap = r >= 7 && r <= 9;
                if (c == 15 && !gap || c == 13 && r == 7) {
                    for (int i = 0; i < 3; i++) {
                        map.markOccupied(p.x(), p.y());
                    }
                } else if (c < 15 || gap) {
                    map.markFree(p.x(), p.y());
                    map.markFree(p.x(), p.y());
                }
            }
        }
        boolean[] closed = new net.smc.sim.map.PathPlanner(Explorer.CLEARANCE).closedCells(map, List.of(), 0);
        assertTrue(closed[14 + 8 * map.cols()] && closed[14 + 7 * map.cols()] && closed[14 + 9 * map.cols()],
                "the doorway clearance closes the way to the gap");
        Explorer explorer = new Explorer(robot, map);
        explorer.start();
        explorer.explore();
        world.step(0.05);
        assertTrue(explorer.isExploring(), "a frontier beyond the gap was chosen");
        world.run(20);
        assertTrue(robot.x > 3.0, "it drove towards the gap: x " + robot.x);
    }

    /** A map of {@code size} x {@code size} m all known free except the unknown cells that {@code unknown} picks. */
    private static OccupancyGrid freeExcept(double size, java.util.function.BiPredicate<Integer, Integer> unknown) {
        OccupancyGrid map = new OccupancyGrid(0, 0, size, size, 0.25);
        for (int r = 0; r < map.rows(); r++) {
            for (int c = 0; c < map.cols(); c++) {
                if (!unknown.test(c, r)) {
                    var p = map.centre(c, r);
                    map.markFree(p.x(), p.y());
                }
            }
        }
        return map;
    }

    /**
     * A robot whose ring cannot see the unknown corner (it has no ring here: the corner stands for
     * the far side of a wall a cell straddles) drives there once, takes what stays unknown there to
     * be hidden, and stops; told to explore again (as the surveyor's policy does every 2 s) it does
     * not drive there again.
     */
    @Test
    void aFrontierWhoseUnknownSideStaysUnknownWhenLookedAt_isNotDrivenToAgain() {
        FakeWorld world = new FakeWorld(4, 4);
        FakeRobot robot = world.robot("r1", 0.5, 0.5, 0).without(RobotHardware.Device.PROXIMITY);
        OccupancyGrid map = freeExcept(4, (c, r) -> c >= 14 && r >= 14);
        Explorer explorer = new Explorer(robot, map);
        explorer.start();
        explorer.explore();
        assertTrue(world.runUntil(() -> !explorer.isExploring(), 60), "it gave the hidden corner up");
        assertTrue(Math.hypot(robot.x - 3.4, robot.y - 3.4) < 1.0, "it went to look: " + robot.x + "," + robot.y);
        assertFalse(explorer.frontier(13, 14), "the cell beside the corner is no frontier any more");
        double x = robot.x;
        double y = robot.y;
        for (int i = 0; i < 10; i++) {
            explorer.explore();
            world.step(0.05);
            assertFalse(explorer.isExploring(), "told to explore again, it finds nothing to drive to");
            world.run(2);
        }
        assertEquals(0, Math.hypot(robot.x - x, robot.y - y), 0.05, "it stayed where it was");
    }

    /**
     * A frontier the robot cannot get to (a wall not on its map pins it: it stalls) is set aside for
     * {@link Explorer#SET_ASIDE_SECONDS}: exploring again at once does not choose it, exploring
     * after that time does.
     */
    @Test
    void aFrontierGivenUpOn_isSetAsideForAWhile_thenTriedAgain() {
        FakeWorld world = new FakeWorld(4, 4).box(1.5, 0, 1.6, 4);
        FakeRobot robot = world.robot("r1", 1.3, 2.1, 0).without(RobotHardware.Device.PROXIMITY);
        OccupancyGrid map = freeExcept(4, (c, r) -> c == 15 && r == 8);
        Explorer explorer = new Explorer(robot, map);
        explorer.start();
        explorer.explore();
        world.step(0.05);
        assertTrue(explorer.isExploring());
        assertTrue(world.runUntil(() -> !explorer.isExploring(), 30), "it gave the frontier up when it stalled");
        assertTrue(robot.x < 1.5, "the wall held it");
        assertTrue(explorer.isSetAside(14, 8) && explorer.isSetAside(15, 7), "the frontier and its neighbours are set aside");
        explorer.explore();
        world.step(0.05);
        assertFalse(explorer.isExploring(), "explored again at once, it does not choose the frontier set aside");
        world.run(Explorer.SET_ASIDE_SECONDS + 1);
        explorer.explore();
        world.step(0.05);
        assertTrue(explorer.isExploring(), "after the time set aside, it tries again");
    }

    /**
     * A cell the ring struck (the side of a thick wall) that rays passing beside it later free again
     * holds the wall's edge: its unknown side is the inside of the wall, and it is no frontier.
     */
    @Test
    void aCellTheRingStruck_isNoFrontierWhenFreedAgain() {
        FakeWorld world = new FakeWorld(4, 4).box(2.0, 0, 3.0, 4);
        FakeRobot robot = world.robot("r1", 1.4, 2.1, 0);
        OccupancyGrid map = new OccupancyGrid(0, 0, 4, 4, 0.25);
        Explorer explorer = new Explorer(robot, map);
        explorer.start();
        world.step(0.05);
        int wallCol = map.col(2.05);
        int row = map.row(2.1);
        assertTrue(map.isOccupied(wallCol, row), "the ring struck the wall's side");
        for (int i = 0; i < 10; i++) {
            map.markFree(2.1, 2.1);   // rays passing beside the edge
        }
        assertTrue(map.isFrontier(wallCol, row), "free again, with the wall's inside unknown beyond it");
        assertFalse(explorer.frontier(wallCol, row), "but no frontier to the robot that struck it");
    }

    @Test
    void merge_fillsWhatTheRobotDoesNotKnow_andKeepsWhatItSaw() {
        FakeWorld world = new FakeWorld(2, 1);
        OccupancyGrid own = new OccupancyGrid(0, 0, 2, 1, 0.5);
        own.markFree(0.25, 0.25);
        Explorer explorer = new Explorer(world.robot("r1", 0.25, 0.25, 0).without(RobotHardware.Device.PROXIMITY), own);
        List<Object> rows = List.of("##.#", "?..?");
        explorer.merge(() -> rows);
        assertTrue(own.isFree(0, 0), "its own observation stands");
        assertTrue(own.isOccupied(1, 0) && own.isFree(2, 0) && own.isFree(1, 1), "the other's cells fill the unknown");
        assertFalse(own.isKnown(0, 1), "unknown in both stays unknown");
    }
}
