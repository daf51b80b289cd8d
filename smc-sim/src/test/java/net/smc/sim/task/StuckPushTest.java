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

    private static final double HALF = 0.16;

    /** The map of {@code world} known up to x 3.1 (its boxes occupied, the rest free), unknown east of that. */
    private static OccupancyGrid knownWest(FakeWorld world) {
        OccupancyGrid map = new OccupancyGrid(0, 0, 8, 4, 0.25);
        for (int r = 0; r < map.rows(); r++) {
            for (int c = 0; c <= 12; c++) {
                var p = map.centre(c, r);
                for (int i = 0; i < 3; i++) {
                    if (world.blocked(p.x(), p.y(), 0.05)) {
                        map.markOccupied(p.x(), p.y());
                    } else {
                        map.markFree(p.x(), p.y());
                    }
                }
            }
        }
        return map;
    }

    /** Steps {@code world} for {@code seconds}; the body (the last box) gives way east to a robot touching it, 1 m at most. */
    private static void pushableBody(FakeWorld world, FakeRobot robot, double[] body, double seconds, double[] touched) {
        for (double t = 0; t < seconds; t += 0.05) {
            world.step(0.05);
            int last = world.boxes.size() - 1;
            if (world.boxes.get(last).near(robot.x, robot.y, 0.15 + 0.03)) {
                touched[0]++;
                if (body[0] < 3.56 && robot.x < body[0]) {
                    body[0] += 0.02;
                    world.boxes.set(last, new FakeWorld.Box(body[0] - HALF, body[1] - HALF, body[0] + HALF, body[1] + HALF));
                }
            }
        }
    }

    /**
     * A body that gives way slides ahead of the robot pushing it: the Explorer then knows it where it
     * was pushed to, not where it was told it lay. (A body pushed into a doorway and still known at
     * its old place sealed the room behind it for the rest of a reconnaissance: its new cells read
     * as a wall, and no way led in.)
     */
    @Test
    void aBodyThatGivesWay_isKnownWhereItWasPushedTo() {
        // The doorway of the sealed world, filled by a body that gives way this time.
        double[] body = {4.125, 2.125};
        FakeWorld world = new FakeWorld(8, 4).box(4, 0, 4.25, 1.75).box(4, 2.5, 4.25, 4)
                .box(body[0] - 0.125, 1.75, body[0] + 0.125, 2.5);
        FakeRobot robot = world.robot("r1", 1.125, 2.125, 0);
        // Known as far as x 5.25, a metre beyond the doorway: the robot must push the body through to get there.
        OccupancyGrid map = sealedMap();
        for (int r = 0; r < map.rows(); r++) {
            for (int c = 17; c <= 20; c++) {
                var p = map.centre(c, r);
                for (int i = 0; i < 3; i++) {
                    map.markFree(p.x(), p.y());
                }
            }
        }
        Explorer explorer = new Explorer(robot, map);
        explorer.pushAside(body[0], body[1]);
        explorer.start();
        explorer.explore();
        for (double t = 0; t < 60 && body[0] < 5.1; t += 0.05) {
            world.step(0.05);
            int last = world.boxes.size() - 1;
            if (world.boxes.get(last).near(robot.x, robot.y, 0.15 + 0.03) && robot.x < body[0]) {
                body[0] += 0.005;   // 0.1 m/s, slower than a pushing robot drives
                world.boxes.set(last, new FakeWorld.Box(body[0] - 0.125, 1.75, body[0] + 0.125, 2.5));
            }
        }
        assertTrue(body[0] > 4.125 + 0.5, "the robot pushed the body out of the doorway: it lies at x " + body[0]);
        assertEquals(1, explorer.bodies().size(), "one body: " + explorer.bodies());
        double known = explorer.bodies().get(0).x();
        assertTrue(Math.abs(known - body[0]) < 0.35, "the body is known at x " + known + ", it lies at x " + body[0]);
    }

    /** With room to go round a body, the robot goes round it: it pushes only where no other way is open. */
    @Test
    void aBodyWithRoomAroundIt_isGoneRound_notPushed() {
        double[] body = {2.56, 2.125};
        FakeWorld world = new FakeWorld(8, 4).box(body[0] - HALF, body[1] - HALF, body[0] + HALF, body[1] + HALF);
        FakeRobot robot = world.robot("r1", 1.125, 2.125, 0);
        Explorer explorer = new Explorer(robot, knownWest(world));
        explorer.pushAside(body[0], body[1]);
        explorer.start();
        explorer.explore();
        double[] touched = new double[1];
        pushableBody(world, robot, body, 10, touched);
        assertTrue(robot.x > 3.0, "the robot went on east: x " + robot.x);
        assertEquals(0, touched[0], "steps the robot touched the body");
        assertEquals(2.56, body[0], 1e-9, "the body was not pushed");
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
