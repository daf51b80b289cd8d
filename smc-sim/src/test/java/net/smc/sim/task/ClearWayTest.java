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

    /** The robot's map of {@link #doorway()}: every cell known, the wall's occupied. */
    private static OccupancyGrid map(FakeWorld world) {
        OccupancyGrid map = new OccupancyGrid(0, 0, 8, 4, 0.25);
        for (int r = 0; r < map.rows(); r++) {
            for (int c = 0; c < map.cols(); c++) {
                var p = map.centre(c, r);
                for (int i = 0; i < 3; i++) {
                    if (world.solid(p.x(), p.y())) {
                        map.markOccupied(p.x(), p.y());
                    } else {
                        map.markFree(p.x(), p.y());
                    }
                }
            }
        }
        return map;
    }

    /** Whether the robot's body (0.32 m across) overlaps the doorway's opening, x 3.84 to 4.41. */
    private static boolean inTheDoorway(FakeRobot robot) {
        return robot.x > 4 - 0.16 && robot.x < 4.25 + 0.16;
    }

    @Test
    void aRobotNoTaskDrives_leavesTheDoorwayItStandsIn_andStopsClearOfIt() {
        FakeWorld world = doorway();
        FakeRobot robot = world.robot("s1", 4.125, 2.0, 0);
        OccupancyGrid map = map(world);
        ClearWay way = ClearWay.install(new TaskContext(robot, map), List.of(new Explorer(robot, map)));
        assertTrue(ClearWay.inPassage(map, map.col(robot.x), map.row(robot.y)), "the doorway is a passage on the map");

        world.run(ClearWay.IDLE_SECONDS - 0.5);
        assertEquals(4.125, robot.x, 1e-9, "it waits before it moves");
        world.run(30);

        assertFalse(inTheDoorway(robot), "still in the doorway at x " + robot.x);
        assertFalse(way.moving(), "it stopped");
        assertEquals(0, robot.speed(), 1e-6, "it stands still");
        assertFalse(ClearWay.inPassage(map, map.col(robot.x), map.row(robot.y)), "it stands in no passage: " + robot.x + ", " + robot.y);
    }

    @Test
    void aRobotInTheOpen_orBesideAWall_staysWhereItIs() {
        FakeWorld world = doorway();
        FakeRobot open = world.robot("s1", 2.0, 2.0, 0);
        FakeRobot wall = world.robot("s2", 3.7, 0.6, 0);
        OccupancyGrid map = map(world);
        ClearWay.install(new TaskContext(open, map), List.of());
        ClearWay.install(new TaskContext(wall, map), List.of());

        world.run(20);

        assertEquals(2.0, open.x, 1e-9);
        assertEquals(2.0, open.y, 1e-9);
        assertEquals(3.7, wall.x, 1e-9);
        assertEquals(0.6, wall.y, 1e-9);
    }

    @Test
    void whileATaskThatDrivesRuns_theWheelsAreTheTasks() {
        FakeWorld world = doorway();
        FakeRobot robot = world.robot("s1", 4.125, 2.0, 0);
        OccupancyGrid map = map(world);
        Navigator navigator = new Navigator(robot, map);
        ClearWay way = ClearWay.install(new TaskContext(robot, map), List.of(navigator));
        navigator.start();   // running, no goal: it holds the robot where it is

        world.run(20);

        assertEquals(4.125, robot.x, 1e-9);
        assertEquals(2.0, robot.y, 1e-9);
        assertFalse(way.moving());

        navigator.stop();    // its role ended: now no task drives
        world.run(30);
        assertFalse(inTheDoorway(robot), "still in the doorway at x " + robot.x);
    }
}
