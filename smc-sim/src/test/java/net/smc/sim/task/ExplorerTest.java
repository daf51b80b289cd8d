package net.smc.sim.task;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
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
}
