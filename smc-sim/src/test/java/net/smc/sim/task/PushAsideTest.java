package net.smc.sim.task;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import net.smc.sim.map.OccupancyGrid;
import org.junit.jupiter.api.Test;

/**
 * A room whose only doorway a dead teammate's body fills on the map: the Explorer finds no way to
 * the room beyond until it knows where the failed teammate's body lies ({@link Explorer#pushAside}),
 * then plans through the body's cells and drives into the doorway (pushing the body is the
 * physics' part, {@code DriveTest}).
 */
class PushAsideTest {
    /**
     * 8 x 4 m: known free west of a wall at column 16 (x 4 to 4.25), unknown east of it; the
     * wall's doorway (rows 7 to 9, y 1.75 to 2.5) is filled by a body, occupied on the map too.
     */
    private static OccupancyGrid sealedDoorway() {
        OccupancyGrid map = new OccupancyGrid(0, 0, 8, 4, 0.25);
        for (int r = 0; r < map.rows(); r++) {
            for (int c = 0; c <= 16; c++) {
                var p = map.centre(c, r);
                if (c == 16) {
                    for (int i = 0; i < 3; i++) {
                        map.markOccupied(p.x(), p.y());
                    }
                } else {
                    map.markFree(p.x(), p.y());
                    map.markFree(p.x(), p.y());
                }
            }
        }
        return map;
    }

    private static Explorer exploring(FakeRobot robot, OccupancyGrid map, boolean told) {
        Explorer explorer = new Explorer(robot, map);
        if (told) {
            explorer.pushAside(4.125, 2.125);
        }
        explorer.start();
        explorer.explore();
        return explorer;
    }

    @Test
    void aBodyInTheOnlyDoorway_sealsTheRoom_untilTheExplorerKnowsItMayPushItAside() {
        FakeWorld sealedWorld = new FakeWorld(8, 4);
        FakeRobot sealedRobot = sealedWorld.robot("r1", 1.125, 2.125, 0);
        Explorer sealed = exploring(sealedRobot, sealedDoorway(), false);
        sealedWorld.step(0.05);
        assertFalse(sealed.isExploring(), "without knowing of the body no frontier is reachable");

        FakeWorld world = new FakeWorld(8, 4);
        FakeRobot robot = world.robot("r1", 1.125, 2.125, 0);
        Explorer explorer = exploring(robot, sealedDoorway(), true);
        world.step(0.05);
        assertTrue(explorer.isExploring(), "a frontier through the body was chosen");
        world.run(20);
        assertTrue(robot.x > 3.3, "it drove up to the body in the doorway: x " + robot.x);
    }

    @Test
    void pushAside_refusesAPositionThatIsNotANumber() {
        FakeWorld world = new FakeWorld(8, 4);
        Explorer explorer = new Explorer(world.robot("r1", 1.125, 2.125, 0), new OccupancyGrid(0, 0, 8, 4, 0.25));
        assertThrows(IllegalArgumentException.class, () -> explorer.pushAside(Double.NaN, 2));
    }

    /** Something right in front of the robot stops it, unless it lies where a body to push lies: then it drives on slowly. */
    @Test
    void somethingInFrontBesideAPushableBody_doesNotStopTheFollower_whichDrivesOnSlowly() {
        for (boolean pushable : new boolean[] {false, true}) {
            FakeWorld world = new FakeWorld(6, 4).box(2 + FakeRobot.WHEEL_BASE / 2 + 0.05, 1.8, 2.8, 2.2);
            FakeRobot robot = world.robot("r1", 2, 2, 0);
            PathFollower follower = new PathFollower(robot, 0.25, 0.12);
            if (pushable) {
                follower.pushable(java.util.List.of(new net.smc.sim.map.Point(2.6, 2)));
            }
            follower.follow(java.util.List.of(new net.smc.sim.map.Point(5, 2)), 0.25);
            PathFollower.Status status = follower.step();
            if (pushable) {
                assertTrue(status == PathFollower.Status.MOVING, "drives on into the body: " + status);
                assertTrue(robot.wantLeft > 0 && robot.wantLeft <= FakeRobot.MAX_SPEED * PathFollower.PUSH_SPEED + 1e-9,
                        "slowly: " + robot.wantLeft);
            } else {
                assertTrue(status == PathFollower.Status.OBSTRUCTED, "stops for an obstacle: " + status);
            }
        }
    }
}
