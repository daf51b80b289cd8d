package net.smc.sim.task;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import net.smc.sim.hardware.Battery;
import net.smc.sim.hardware.Camera;
import net.smc.sim.hardware.ChemicalSensor;
import net.smc.sim.hardware.ControlLoop;
import net.smc.sim.hardware.Drive;
import net.smc.sim.hardware.Odometry;
import net.smc.sim.hardware.Pose;
import net.smc.sim.hardware.ProximitySensors;
import net.smc.sim.hardware.Radio;
import net.smc.sim.hardware.RobotHardware;
import net.smc.sim.map.OccupancyGrid;
import net.smc.sim.map.Point;
import org.junit.jupiter.api.Test;

/**
 * A robot pushing a failed teammate's body that does not give (wedged against a jamb, say) stands
 * still, but its position fix makes its pose jitter by a few centimetres: the Explorer must still
 * take that for no progress and give its frontier up, or it pushes to the end of the mission (a
 * surveyor did so for 650 s in a doorway of the house).
 */
class StuckPushTest {
    /** The wall at x 4 to 4.25 across the 8 x 4 m world, its doorway (y 1.75 to 2.5) filled by a box that cannot move. */
    private static FakeWorld sealedWorld() {
        return new FakeWorld(8, 4).box(4, 0, 4.25, 1.75).box(4, 2.5, 4.25, 4).box(4, 1.75, 4.25, 2.5);
    }

    /** The map: known free west of the wall, the wall and the body occupied, unknown east of it. */
    private static OccupancyGrid sealedMap() {
        OccupancyGrid map = new OccupancyGrid(0, 0, 8, 4, 0.25);
        for (int r = 0; r < map.rows(); r++) {
            for (int c = 0; c <= 16; c++) {
                var p = map.centre(c, r);
                for (int i = 0; i < 3; i++) {
                    if (c == 16) {
                        map.markOccupied(p.x(), p.y());
                    } else {
                        map.markFree(p.x(), p.y());
                    }
                }
            }
        }
        return map;
    }

    /** An Explorer on {@code robot}, its pose jittering, told of the body wedged in the doorway, exploring. */
    private static Explorer exploringTowardsTheWedgedBody(FakeWorld world, FakeRobot robot) {
        Explorer explorer = new Explorer(new Jittering(robot, world), sealedMap());
        explorer.pushAside(4.125, 2.125);
        explorer.start();
        explorer.explore();
        return explorer;
    }

    @Test
    void aRobotPushingABodyThatDoesNotGive_givesItsFrontierUp_thoughItsPoseJitters() {
        FakeWorld world = sealedWorld();
        FakeRobot robot = world.robot("r1", 1.125, 2.125, 0);
        Explorer explorer = exploringTowardsTheWedgedBody(world, robot);
        double pushingSince = Double.NaN;
        double gaveUpAt = Double.NaN;
        while (world.time < 60 && Double.isNaN(gaveUpAt)) {
            world.step(0.05);
            if (Double.isNaN(pushingSince) && robot.x > 3.7) {
                pushingSince = world.time;
            } else if (!Double.isNaN(pushingSince) && robot.wantLeft < 0 && robot.wantRight < 0) {
                gaveUpAt = world.time;   // backing off: the frontier was given up
            }
        }
        assertFalse(Double.isNaN(pushingSince), "the robot reached the body: x " + robot.x);
        assertTrue(robot.x < 3.95, "the body did not give: x " + robot.x);
        assertFalse(Double.isNaN(gaveUpAt), "still pushing at " + world.time + " s, since " + pushingSince + " s");
        assertTrue(gaveUpAt - pushingSince <= Explorer.CREEP_SECONDS + 5,
                "gave up " + (gaveUpAt - pushingSince) + " s after it began to push");
    }

    /**
     * A body that gives way slides ahead of the robot pushing it: the Explorer then knows it where it
     * was pushed to, not where it was told it lay. (A body pushed into a doorway and still known at
     * its old place sealed the room behind it for the rest of a reconnaissance: its new cells read
     * as a wall, and no way led in.) Pushing into what does not give moves no body.
     */
    @Test
    void aBodyThatGivesWay_isKnownWhereItWasPushedTo() {
        FakeWorld world = new FakeWorld(8, 4);
        double half = 0.16;
        double[] body = {2.56, 2.125};
        world.box(body[0] - half, body[1] - half, body[0] + half, body[1] + half);
        FakeRobot robot = world.robot("r1", 1.125, 2.125, 0);
        OccupancyGrid map = new OccupancyGrid(0, 0, 8, 4, 0.25);
        for (int r = 0; r < map.rows(); r++) {
            for (int c = 0; c <= 12; c++) {
                var p = map.centre(c, r);
                for (int i = 0; i < 3; i++) {
                    if (Math.abs(p.x() - body[0]) < 0.3 && Math.abs(p.y() - body[1]) < 0.3) {
                        map.markOccupied(p.x(), p.y());
                    } else {
                        map.markFree(p.x(), p.y());
                    }
                }
            }
        }
        Explorer explorer = new Explorer(robot, map);
        explorer.pushAside(body[0], body[1]);
        explorer.start();
        explorer.explore();
        for (int i = 0; i < 200; i++) {
            world.step(0.05);
            // The body gives way: whatever the robot's front reaches, it slides east, 1 m at most.
            if (robot.x + 0.15 + 0.03 >= body[0] - half && body[0] < 3.56) {
                body[0] += 0.02;
                world.boxes.set(0, new FakeWorld.Box(body[0] - half, body[1] - half, body[0] + half, body[1] + half));
            }
        }
        assertTrue(body[0] > 2.56 + 0.5, "the robot pushed the body east: it lies at x " + body[0]);
        assertEquals(1, explorer.bodies().size(), "one body: " + explorer.bodies());
        double known = explorer.bodies().get(0).x();
        assertTrue(Math.abs(known - body[0]) < 0.3, "the body is known at x " + known + ", it lies at x " + body[0]);
    }

    @Test
    void aBodyThatDoesNotGive_staysWhereItWasKnown() {
        FakeWorld world = sealedWorld();
        FakeRobot robot = world.robot("r1", 1.125, 2.125, 0);
        Explorer explorer = exploringTowardsTheWedgedBody(world, robot);
        world.run(20);
        assertTrue(robot.x > 3.6, "the robot reached the body: x " + robot.x);
        // Its pose jitters by up to 8 cm (the position fix), so the body may be taken to lie as far
        // off, no further: the robot never gets on, and the body does not slide.
        assertEquals(1, explorer.bodies().size(), "one body: " + explorer.bodies());
        Point known = explorer.bodies().get(0);
        assertTrue(known.distanceTo(4.125, 2.125) <= 0.1, "the wedged body is known at " + known);
    }

    @Test
    void aStallWatch_takesJitterWithinItsDistanceForNoMove() {
        StallWatch creep = new StallWatch(15, 0.3);
        StallWatch stall = new StallWatch(4);
        boolean creepStalled = false;
        boolean stallStalled = false;
        for (double t = 0; t <= 16; t += 0.05) {
            Pose p = new Pose(2 + 0.05 * Math.cos(Math.PI * t), 2, 0);
            creepStalled |= creep.stalled(t, p);
            stallStalled |= stall.stalled(t, p);
        }
        assertTrue(creepStalled, "10 cm of jitter is no progress over 0.3 m");
        assertFalse(stallStalled, "10 cm of jitter is a move over 5 cm");
        assertEquals(false, new StallWatch(15, 0.3).stalled(0, new Pose(0, 0, 0)));
        assertThrows(IllegalArgumentException.class, () -> new StallWatch(15, 0));
        assertThrows(IllegalArgumentException.class, () -> new StallWatch(Double.NaN, 0.3));
    }

    /** The robot with its odometry's x off by up to 8 cm, back and forth every 2 s: a position fix's jitter. */
    private record Jittering(FakeRobot robot, FakeWorld world) implements RobotHardware {
        @Override public String id() { return robot.id(); }
        @Override public boolean has(Device device) { return robot.has(device); }
        @Override public Drive drive() { return robot.drive(); }
        @Override public ProximitySensors proximity() { return robot.proximity(); }
        @Override public Camera camera() { return robot.camera(); }
        @Override public ChemicalSensor chemical() { return robot.chemical(); }
        @Override public Battery battery() { return robot.battery(); }
        @Override public Radio radio() { return robot.radio(); }
        @Override public void control(Object owner, ControlLoop loop) { robot.control(owner, loop); }

        @Override
        public Odometry odometry() {
            return new Odometry() {
                @Override
                public Pose pose() {
                    Pose p = robot.odometry().pose();
                    return new Pose(p.x() + 0.08 * Math.cos(Math.PI * world.time), p.y(), p.heading());
                }

                @Override
                public double travelled() {
                    return robot.odometry().travelled();
                }
            };
        }
    }
}
