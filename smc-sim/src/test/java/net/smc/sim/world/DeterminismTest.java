package net.smc.sim.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;

import java.util.Arrays;

import net.smc.core.transport.sim.SimulationScheduler;
import net.smc.sim.arena.ArenaReader;
import net.smc.sim.hardware.Pose;
import net.smc.sim.robot.SimRobot;
import org.junit.jupiter.api.Test;

class DeterminismTest {

    /** Runs the rescue arena for 60 s with three wandering robots; the trace has every pose and reading. */
    private static String trace(long seed, boolean observerReadsSensors) throws Exception {
        SimulationScheduler scheduler = new SimulationScheduler();
        SimWorld world = SimWorld.builder(ArenaReader.read(Worlds.worldFile("rescue.xml")), scheduler).seed(seed).build();
        for (String id : new String[] {"r1", "r2", "r3"}) {
            SimRobot robot = world.addRobot(id, id);
            robot.control(robot, (time, dt) -> {
                double[] ir = robot.proximity().read();
                double left = ir[0] + ir[1] + ir[2];
                double right = ir[13] + ir[14] + ir[15];
                double turn = (left - right) * 2 + (robot.camera().look().isEmpty() ? 0.05 : -0.05);
                robot.drive().setWheelSpeeds(0.4 - turn, 0.4 + turn);
            });
        }
        StringBuilder out = new StringBuilder();
        world.addListener(new WorldStepListener() {
            @Override
            public void stepped(SimWorld w) {
                out.append(w.steps());
                for (SimRobot robot : w.robots()) {
                    Pose p = robot.pose();
                    Pose o = robot.odometry().pose();
                    out.append(' ').append(robot.id()).append(' ').append(p.x()).append(',').append(p.y()).append(',')
                            .append(p.heading()).append(" odo ").append(o.x()).append(',').append(o.y())
                            .append(" bat ").append(robot.battery().level())
                            .append(robot.disabled() ? " off " + robot.disabledBy() : "");
                    if (observerReadsSensors) {
                        robot.proximity().read();
                        robot.camera().look();
                        robot.radio().neighbours();
                    }
                }
                out.append('\n');
            }

            @Override
            public void disabled(SimWorld w, SimRobot robot, String cause) {
                out.append("disabled ").append(robot.id()).append(' ').append(cause).append('\n');
            }
        });
        world.start();
        scheduler.runFor(60_000);
        assertEquals(3_000, world.steps());
        return out.toString();
    }

    @Test
    void sameSeed_replaysTheRunByteForByte() throws Exception {
        String first = trace(42, false);
        String second = trace(42, false);
        assertEquals(first, second);
        assertEquals(3_000, first.lines().filter(l -> !l.startsWith("disabled")).count());
    }

    @Test
    void differentSeed_givesADifferentRun() throws Exception {
        String a = trace(42, false);
        String b = trace(43, false);
        assertNotEquals(a, b);
        String[] lastA = a.lines().reduce((x, y) -> y).orElseThrow().split(" ");
        String[] lastB = b.lines().reduce((x, y) -> y).orElseThrow().split(" ");
        assertNotEquals(Arrays.asList(lastA), Arrays.asList(lastB));
    }

    @Test
    void observersReadingSensors_doNotChangeTheRun() throws Exception {
        assertEquals(trace(42, false), trace(42, true));
    }
}
