package net.smc.sim.task;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import net.smc.sim.map.OccupancyGrid;
import net.smc.sim.map.Point;
import net.smc.sim.robot.KoalaSpec;
import net.smc.sim.robot.SimRobot;
import net.smc.core.transport.sim.SimulationScheduler;
import net.smc.sim.world.SimWorld;
import net.smc.sim.world.WorldStepListener;
import net.smc.sim.world.Worlds;
import org.junit.jupiter.api.Test;

/**
 * A dead teammate in a doorway, in the physics world: a Navigator that was not told of the body
 * finds no way past it and gives up; told where the body lies ({@link Navigator#pushAside}), it
 * plans through the body's cells and pushes it out of the doorway, or, where there is room beside
 * the body, drives around it without touching it.
 */
class NavigatorPushAsideTest {
    /** A world stepped by its own scheduler (the tasks' clock), with a position fix every second as in the house. */
    private static House world(String walls) {
        SimulationScheduler clock = new SimulationScheduler();
        SimWorld world = SimWorld.builder(Worlds.arena(8, 4, walls + "<start id='s0' x='1' y='2'/>"), clock).seed(3).build();
        world.addListener(new WorldStepListener() {
            @Override
            public void stepped(SimWorld w) {
                if (w.steps() % 50 == 0) {
                    w.robots().forEach(SimRobot::positionFix);
                }
            }
        });
        return new House(world, clock);
    }

    /** A world and the scheduler that steps it. */
    private record House(SimWorld world, SimulationScheduler clock) {
        SimRobot addDead(double x, double y) {
            SimRobot dead = world.addRobot("dead", Worlds.start(x, y, 90), KoalaSpec.koala().withIrRange(2.0));
            dead.disable("battery");
            return dead;
        }
    }

    /** A wall across x = 4 with one doorway (y 1.6 to 2.4); a dead robot stands at (4, deadY). */
    private static House doorway(double deadY) {
        House house = world("<wall x1='4' y1='0' x2='4' y2='1.6'/><wall x1='4' y1='2.4' x2='4' y2='4'/>");
        house.addDead(4, deadY);
        return house;
    }

    private record Drive(SimRobot robot, SimRobot dead, EventLog log) { }

    /** A robot at (1, 2) goes to (7, 2) (beyond the doorway), told of a body at (4, bodyY) or not; 200 s at most. */
    private static Drive driveThrough(House house, boolean told, double bodyY) throws Exception {
        SimWorld world = house.world();
        SimRobot robot = world.addRobot("r1", Worlds.start(1, 2, 0), KoalaSpec.koala().withIrRange(2.0));
        Navigator nav = new Navigator(robot, new OccupancyGrid(0, 0, 8, 4, 0.25), Explorer.CLEARANCE);
        EventLog log = new EventLog().watch(nav);
        if (told) {
            nav.pushAside(4, bodyY);
        }
        nav.start();
        nav.goTo(7, 2);
        world.start();
        house.clock().runUntil(() -> !nav.isMoving(), 200_000);
        return new Drive(robot, world.robot("dead"), log);
    }

    @Test
    void notToldOfTheBody_itFindsNoWayThroughTheDoorway_andGivesUp() throws Exception {
        Drive d = driveThrough(doorway(2), false, 2);
        assertEquals(1, d.log().of("blocked").size(), "blocked: " + d.log().lines);
        assertEquals(List.of(), d.log().of("arrived"));
        assertTrue(d.robot().pose().x() < 4, "still on the near side: " + d.robot().pose());
        assertEquals(4, d.dead().pose().x(), 0.05, "the body was not moved: " + d.dead().pose());
    }

    @Test
    void toldOfTheBody_itPushesItOutOfTheDoorway_andArrives() throws Exception {
        Drive d = driveThrough(doorway(2), true, 2);
        assertTrue(d.log().of("blocked").isEmpty(), "events: " + d.log().lines);
        assertEquals(1, d.log().of("arrived").size(), "events: " + d.log().lines);
        assertTrue(d.robot().pose().x() > 6.7, "through the doorway: " + d.robot().pose());
        assertTrue(d.dead().pose().distanceTo(4, 2) > 0.3, "the body was pushed out of the doorway: " + d.dead().pose());
        d.log().assertNoErrors();
    }

    @Test
    void toldOfABodyWithRoomBesideIt_itDrivesAroundWithoutPushing() throws Exception {
        // an open field: the body stands on the straight line to the goal, with all the room around it
        House open = world("");
        open.addDead(4, 2);
        Drive d = driveThrough(open, true, 2);
        assertEquals(1, d.log().of("arrived").size(), "events: " + d.log().lines);
        assertEquals(4, d.dead().pose().x(), 0.02, "the body was not pushed: " + d.dead().pose());
        assertEquals(2, d.dead().pose().y(), 0.02, "the body was not pushed: " + d.dead().pose());
    }

    @Test
    void aBodyToldOfAgain_isKeptOnce_andAPositionThatIsNotANumberIsRefused() {
        SimWorld world = Worlds.world(Worlds.arena(8, 4, "<start id='s0' x='1' y='2'/>"), 3);
        SimRobot robot = world.addRobot("r1", Worlds.start(1, 2, 0), KoalaSpec.koala());
        HazardDetector detector = new HazardDetector(robot, new OccupancyGrid(0, 0, 8, 4, 0.25));
        detector.pushAside(4, 2);
        detector.pushAside(4, 2);
        detector.pushAside(6, 1);
        assertEquals(List.of(new Point(4, 2), new Point(6, 1)), detector.bodies(), "the detector's navigator was told");
        assertThrows(IllegalArgumentException.class, () -> detector.pushAside(Double.NaN, 2));
        assertThrows(IllegalArgumentException.class, () -> new Navigator(robot, new OccupancyGrid(0, 0, 8, 4, 0.25))
                .pushAside(1, Double.POSITIVE_INFINITY));
    }
}
