package net.smc.sim.robot;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import net.smc.sim.hardware.ChemicalSensor;
import net.smc.sim.hardware.Radio;
import net.smc.sim.hardware.Sighting;
import net.smc.sim.arena.Arena;
import net.smc.sim.world.SimWorld;
import net.smc.sim.world.Worlds;
import org.dyn4j.dynamics.Body;
import org.junit.jupiter.api.Test;

class SensorsTest {
    private static final String START = "<start id='s0' x='0.5' y='0.5'/>";

    @Test
    void infrared_readsAWallsDistanceWithinItsNoise() {
        // the fence's inner face is at x = 4; the robot's front face at x = 3.74 + 0.16 = 3.90
        SimWorld world = Worlds.world(Worlds.arena(4, 4, START), 3);
        SimRobot robot = world.addRobot("r", Worlds.start(3.74, 2, 0), KoalaSpec.koala());
        double sigma = robot.spec().irNoise();
        int front = 0; // sensor 0 points 8 degrees left of the heading, through the front face
        double expected = 0.10 / Math.cos(robot.proximity().angle(front));
        double sum = 0;
        double min = Double.MAX_VALUE;
        double max = -Double.MAX_VALUE;
        int n = 400;
        for (int i = 0; i < n; i++) {
            world.step();
            double reading = robot.proximity().read()[front];
            assertEquals(expected, reading, 5 * sigma, "step " + i);
            sum += reading;
            min = Math.min(min, reading);
            max = Math.max(max, reading);
        }
        assertEquals(expected, sum / n, 4 * sigma / Math.sqrt(n), "the noise is unbiased");
        assertTrue(max - min > sigma, "the readings are noisy: " + min + " .. " + max);
    }

    @Test
    void infrared_readsRangeWhereNothingIsNearAndSeesOtherRobots() {
        SimWorld world = Worlds.world(Worlds.arena(6, 6, START), 3);
        SimRobot robot = world.addRobot("r", Worlds.start(3, 3, 0), KoalaSpec.koala().withIrNoise(0));
        world.addRobot("other", Worlds.start(3, 3.5, 0), KoalaSpec.koala());
        world.step();
        double[] read = robot.proximity().read();
        assertEquals(16, read.length);
        for (int i = 0; i < read.length; i++) {
            double angle = Math.toDegrees(robot.proximity().angle(i));
            if (angle > 70 && angle < 110) {
                // the other robot's near face is at y = 3.34; this robot's left face at 3.16
                assertTrue(read[i] < 0.2, "sensor at " + angle + " reads " + read[i]);
            } else if (angle < 0) {
                assertEquals(robot.proximity().range(), read[i], 1e-12, "sensor at " + angle);
            }
        }
        assertEquals(0.18, read[4] * Math.sin(Math.toRadians(80)), 1e-6, "sensor at 80 degrees");
    }

    @Test
    void camera_seesWithinItsFieldOfViewAndRange() {
        Arena open = Worlds.arena(10, 6, START + "<target id='soldier' x='5' y='3'/>");
        SimWorld world = Worlds.world(open, 1);
        SimRobot ahead = world.addRobot("ahead", Worlds.start(2, 3, 0), KoalaSpec.koala());
        SimRobot aside = world.addRobot("aside", Worlds.start(5, 1, 0), KoalaSpec.koala());
        SimRobot behind = world.addRobot("behind", Worlds.start(8, 3, 0), KoalaSpec.koala());
        world.step();
        Sighting soldier = find(ahead.camera().look(), "soldier");
        assertEquals("soldier", soldier.kind());
        assertEquals(5 - 2.16, soldier.distance(), 0.1);
        assertEquals(0, soldier.bearing(), 0.02);
        assertEquals(null, find(aside.camera().look(), "soldier"), "the soldier is 90 degrees to its left");
        assertEquals(null, find(behind.camera().look(), "soldier"), "the soldier is behind it");
        SimWorld far = Worlds.world(open, 1);
        SimRobot distant = far.addRobot("far", Worlds.start(0.5, 3, 0), KoalaSpec.koala()
                .withOdometryNoise(0));
        far.step();
        assertTrue(4.34 < distant.spec().cameraRange(), "sanity: 4.34 m is within range");
        assertTrue(find(distant.camera().look(), "soldier") != null);
        SimWorld wide = Worlds.world(Worlds.arena(20, 6, START + "<target id='soldier' x='15' y='3'/>"), 1);
        SimRobot tooFar = wide.addRobot("tooFar", Worlds.start(2, 3, 0), KoalaSpec.koala());
        wide.step();
        assertEquals(null, find(tooFar.camera().look(), "soldier"), "12.8 m is beyond the camera's 6 m");
    }

    @Test
    void camera_doesNotSeeThroughWalls() {
        Arena walled = Worlds.arena(10, 6, START + "<target id='soldier' x='6' y='3'/><wall x1='4' y1='1' x2='4' y2='5'/>"
                + "<hazard id='h' x='3.5' y='3.5' effect='0.3'/>");
        SimWorld world = Worlds.world(walled, 1);
        SimRobot robot = world.addRobot("r", Worlds.start(2, 3, 0), KoalaSpec.koala());
        world.step();
        List<Sighting> seen = robot.camera().look();
        assertEquals(null, find(seen, "soldier"));
        assertTrue(find(seen, "hazard:h") != null, "the hazard on this side of the wall is seen: " + seen);
    }

    @Test
    void chemicalSensor_sensesWithinTheEffectPlusItsRadius() {
        Arena arena = Worlds.arena(10, 6, START + "<hazard id='h' kind='chemical' x='5' y='3' effect='0.5'/>");
        SimWorld world = Worlds.world(arena, 1);
        double reach = 0.5 + KoalaSpec.koala().chemicalRadius();
        SimRobot inside = world.addRobot("in", Worlds.start(5 - reach + 0.05, 3, 0), KoalaSpec.koala());
        SimRobot nearer = world.addRobot("nearer", Worlds.start(5, 3 + 0.8, 0), KoalaSpec.koala());
        SimRobot outside = world.addRobot("out", Worlds.start(5 + reach + 0.05, 3, 0), KoalaSpec.koala());
        world.step();
        List<ChemicalSensor.Reading> in = inside.chemical().sense();
        assertEquals(1, in.size());
        assertEquals("hazard:h", in.get(0).tag());
        assertEquals("chemical", in.get(0).kind());
        assertTrue(in.get(0).strength() > 0 && in.get(0).strength() < 0.1, in.toString());
        assertTrue(nearer.chemical().sense().get(0).strength() > in.get(0).strength());
        assertTrue(outside.chemical().sense().isEmpty());
    }

    @Test
    void disablingHazard_stopsTheDriveAndSilencesTheRadio() {
        Arena arena = Worlds.arena(10, 6, START + "<hazard id='h' x='5' y='3' radius='0.15' effect='0.8' disables='true'/>");
        SimWorld world = Worlds.world(arena, 1);
        SimRobot robot = world.addRobot("r", Worlds.start(2, 3, 0), KoalaSpec.koala());
        SimRobot peer = world.addRobot("peer", Worlds.start(2, 5, 0), KoalaSpec.koala());
        robot.control(this, (time, dt) -> robot.drive().setWheelSpeeds(0.5, 0.5));
        assertTrue(peer.radio().linkQuality("r") > 0);
        for (int i = 0; i < 1_000 && !robot.disabled(); i++) {
            world.step();
        }
        assertEquals("hazard:h", robot.disabledBy());
        assertFalse(robot.drive().working());
        assertTrue(robot.pose().distanceTo(5, 3) <= 0.8);
        double x = robot.pose().x();
        for (int i = 0; i < 100; i++) {
            world.step();
        }
        assertEquals(x, robot.pose().x(), 1e-3, "a disabled robot does not drive on");
        assertTrue(robot.radio().neighbours().isEmpty());
        assertEquals(0, peer.radio().linkQuality("r"));
    }

    @Test
    void infrared_readAgainInTheSameMoment_givesTheSameReadingsWithoutCastingAgain() {
        CountingGround ground = new CountingGround();
        SimRobot robot = new SimRobot(ground, "r", 0, KoalaSpec.koala(), Worlds.start(1, 1, 0));
        double[] first = robot.proximity().read();
        double[] again = robot.proximity().read();
        assertEquals(1, ground.casts, "one fan of rays for two reads in one moment");
        assertArrayEquals(first, again);
        assertNotSame(first, again, "each read gets its own array");
        again[0] = -1;
        assertEquals(first[0], robot.proximity().read()[0], "a caller's change does not reach the next read");
        ground.moment++;
        ground.distance = 0.05;
        double[] moved = robot.proximity().read();
        assertEquals(2, ground.casts, "a new moment casts anew");
        assertTrue(moved[0] < first[0], moved[0] + " after the world changed, " + first[0] + " before");
    }

    @Test
    void infrared_onAGroundThatKeepsNoMoment_readsAnewEachTime() {
        CountingGround ground = new CountingGround();
        ground.moment = RobotGround.NO_MOMENT;
        SimRobot robot = new SimRobot(ground, "r", 0, KoalaSpec.koala(), Worlds.start(1, 1, 0));
        robot.proximity().read();
        robot.proximity().read();
        assertEquals(2, ground.casts);
    }

    @Test
    void infrared_readBetweenSteps_seesWhereThePhysicsMovedTheRobot() {
        // driving at a wall: read by its control loop before the physics moves it, and again after
        SimWorld world = Worlds.world(Worlds.arena(4, 4, START), 3);
        SimRobot robot = world.addRobot("r", Worlds.start(3.66, 2, 0), KoalaSpec.koala().withIrNoise(0));
        double[][] inLoop = new double[1][];
        robot.control(this, (time, dt) -> {
            inLoop[0] = robot.proximity().read();
            robot.drive().setWheelSpeeds(0.3, 0.3);
        });
        for (int i = 0; i < 15; i++) {
            world.step();
        }
        assertTrue(inLoop[0][0] < robot.proximity().range(), "the wall is in range: " + inLoop[0][0]);
        double[] after = robot.proximity().read();
        assertTrue(after[0] < inLoop[0][0] - 1e-4, "after the step " + after[0] + ", in the step's loop " + inLoop[0][0]);
    }

    /** A ground whose every ray hits at {@code distance}, counting the fans cast. */
    private static final class CountingGround implements RobotGround {
        int casts;
        long moment;
        double distance = 0.1;

        @Override
        public Arena arena() {
            return Worlds.arena(4, 4, START);
        }

        @Override
        public Iterable<SimRobot> robots() {
            return List.of();
        }

        @Override
        public void castRays(double[] x, double[] y, double[] angle, double maxLength, Body self, double[] out) {
            casts++;
            java.util.Arrays.fill(out, distance);
        }

        @Override
        public boolean clearLine(double ax, double ay, double bx, double by) {
            return true;
        }

        @Override
        public double gaussian(long stream, int channel) {
            return 0.5;
        }

        @Override
        public long moment() {
            return moment;
        }

        @Override
        public Radio radio(String id) {
            throw new UnsupportedOperationException("no radio here");
        }
    }

    private static Sighting find(List<Sighting> seen, String tag) {
        return seen.stream().filter(s -> s.tag().equals(tag)).findFirst().orElse(null);
    }
}
