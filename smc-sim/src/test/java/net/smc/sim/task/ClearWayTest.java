package net.smc.sim.task;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import net.smc.sim.map.OccupancyGrid;
import org.junit.jupiter.api.Test;

/**
 * A robot that no task drives does not stay in a doorway: a surveyor that took over as commander
 * stood for the rest of a mission in the 1 m doorway of the room it was about to explore, and both
 * detectors sent into the room gave their suspect up at the door.
 */
class ClearWayTest {
    /** A wall at x 4 to 4.25 across the 8 x 4 m world with a 1 m doorway at y 1.5 to 2.5. */
    private static FakeWorld doorway() {
        return new FakeWorld(8, 4).box(4, 0, 4.25, 1.5).box(4, 2.5, 4.25, 4);
    }

    /** {@code navigators} run a moment and stop: the roles that drove their robots ended. */
    private static void driveAMomentAndStop(FakeWorld world, Navigator... navigators) {
        for (Navigator n : navigators) {
            n.start();
        }
        world.run(0.5);
        for (Navigator n : navigators) {
            n.stop();
        }
    }

    /** Whether the robot's body (0.32 m across) overlaps the doorway's opening, x 3.84 to 4.41. */
    private static boolean inTheDoorway(FakeRobot robot) {
        return robot.x > 4 - 0.16 && robot.x < 4.25 + 0.16;
    }

    @Test
    void aRobotNoTaskDrivesAnyMore_leavesTheDoorwayItStandsIn_andStopsClearOfIt() {
        FakeWorld world = doorway();
        FakeRobot robot = world.robot("s1", 4.125, 2.0, 0);
        OccupancyGrid map = world.mapped(0.25);
        Navigator navigator = new Navigator(robot, map);
        ClearWay way = ClearWay.install(new TaskContext(robot, map), List.of(navigator));
        assertTrue(ClearWay.inPassage(map, map.col(robot.x), map.row(robot.y)), "the doorway is a passage on the map");
        driveAMomentAndStop(world, navigator);

        world.run(ClearWay.IDLE_SECONDS - 0.5);
        assertEquals(4.125, robot.x, 1e-9, "it waits before it moves");
        world.run(30);

        assertFalse(inTheDoorway(robot), "still in the doorway at x " + robot.x);
        assertFalse(way.moving(), "it stopped");
        assertEquals(0, robot.speed(), 1e-6, "it stands still");
        assertTrue(Math.hypot(robot.x - 4.125, robot.y - 2.0) >= ClearWay.MIN_MOVE - 0.2, "it went about a metre: " + robot.x + ", " + robot.y);
        assertFalse(ClearWay.inPassage(map, map.col(robot.x), map.row(robot.y)), "it stands in no passage: " + robot.x + ", " + robot.y);
    }

    /**
     * A robot that no task has driven stays where it was placed, in a passage too: at the house's
     * entrance the robots parked round the aggregator made one on its map.
     */
    @Test
    void aRobotNoTaskHasDriven_staysWhereItWasPlaced_evenInADoorway() {
        FakeWorld world = doorway();
        FakeRobot robot = world.robot("a1", 4.125, 2.0, 0);
        OccupancyGrid map = world.mapped(0.25);
        ClearWay.install(new TaskContext(robot, map), List.of(new Navigator(robot, map)));

        world.run(30);

        assertStandsAt(robot, 4.125, 2.0);
    }

    @Test
    void aRobotInTheOpen_orBesideAWall_staysWhereItIs() {
        FakeWorld world = doorway();
        FakeRobot open = world.robot("s1", 2.0, 2.0, 0);
        FakeRobot wall = world.robot("s2", 3.7, 0.6, 0);
        OccupancyGrid map = world.mapped(0.25);
        Navigator first = new Navigator(open, map);
        Navigator second = new Navigator(wall, map);
        ClearWay.install(new TaskContext(open, map), List.of(first));
        ClearWay.install(new TaskContext(wall, map), List.of(second));
        driveAMomentAndStop(world, first, second);

        world.run(20);

        assertStandsAt(open, 2.0, 2.0);
        assertStandsAt(wall, 3.7, 0.6);
    }

    @Test
    void whileATaskThatDrivesRuns_theWheelsAreTheTasks() {
        FakeWorld world = doorway();
        FakeRobot robot = world.robot("s1", 4.125, 2.0, 0);
        OccupancyGrid map = world.mapped(0.25);
        Navigator navigator = new Navigator(robot, map);
        ClearWay way = ClearWay.install(new TaskContext(robot, map), List.of(navigator));
        navigator.start();   // running, no goal: it holds the robot where it is

        world.run(20);

        assertStandsAt(robot, 4.125, 2.0);
        assertFalse(way.moving());

        navigator.stop();    // its role ended: now no task drives
        world.run(30);
        assertFalse(inTheDoorway(robot), "still in the doorway at x " + robot.x);
    }

    /**
     * A doorway whose jambs a map shows in the row beside the robot's only (a thin wall lies on the
     * edge of two rows of cells, and the map has worn one of them away) is still a passage.
     */
    @Test
    void aDoorwayWhoseJambsAreInTheNextRow_isAPassage() {
        OccupancyGrid map = new OccupancyGrid(0, 0, 8, 4, 0.25);
        for (int r = 0; r < map.rows(); r++) {
            for (int c = 0; c < map.cols(); c++) {
                var p = map.centre(c, r);
                boolean jamb = r == 7 && (c == 14 || c == 19);   // row 7 (y 1.75 to 2): one jamb each side, 1 m apart
                for (int i = 0; i < 3; i++) {
                    if (jamb) {
                        map.markOccupied(p.x(), p.y());
                    } else {
                        map.markFree(p.x(), p.y());
                    }
                }
            }
        }
        assertTrue(ClearWay.inPassage(map, 16, 8), "between the jambs, in the row above theirs");
        assertFalse(ClearWay.inPassage(map, 16, 10), "two rows above them");
        assertFalse(ClearWay.inPassage(map, 10, 7), "in their row, far from both");
    }

    /** Driven before, a robot whose cell boots again keeps that: its new behaviour clears the way too. */
    @Test
    void aRobotWhoseCellBootsAgain_keepsHavingBeenDriven() {
        FakeWorld world = doorway();
        FakeRobot robot = world.robot("s1", 4.125, 2.0, 0);
        OccupancyGrid map = world.mapped(0.25);
        Navigator before = new Navigator(robot, map);
        ClearWay first = ClearWay.install(new TaskContext(robot, map), List.of(before));
        driveAMomentAndStop(world, before);
        robot.control(first, null);   // the cell boots again: its behaviour is made anew

        ClearWay.install(new TaskContext(robot, map), List.of(new Navigator(robot, map)), first);
        world.run(30);

        assertFalse(inTheDoorway(robot), "still in the doorway at x " + robot.x);
    }

    /** The robot stands exactly where it was placed: it was not moved. */
    private static void assertStandsAt(FakeRobot robot, double x, double y) {
        assertEquals(x, robot.x, 1e-9);
        assertEquals(y, robot.y, 1e-9);
    }
}
