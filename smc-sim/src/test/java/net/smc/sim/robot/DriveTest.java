package net.smc.sim.robot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import net.smc.sim.hardware.Pose;
import net.smc.sim.world.SimWorld;
import net.smc.sim.world.Worlds;
import org.junit.jupiter.api.Test;

class DriveTest {

    /** Steers towards (gx, gy) by its odometry, slowing near it; stops within 5 cm. */
    static void goTo(SimRobot robot, double gx, double gy) {
        robot.control("goto", (time, dt) -> {
            Pose p = robot.odometry().pose();
            double distance = p.distanceTo(gx, gy);
            if (distance < 0.05) {
                robot.drive().stop();
                return;
            }
            double error = Math.IEEEremainder(Math.atan2(gy - p.y(), gx - p.x()) - p.heading(), 2 * Math.PI);
            double forward = Math.min(robot.drive().maxSpeed(), distance) * Math.max(0, Math.cos(error));
            double turn = 0.4 * error;
            robot.drive().setWheelSpeeds(forward - turn, forward + turn);
        });
    }

    @Test
    void simpleController_reachesItsGoal() {
        SimWorld world = Worlds.world(Worlds.arena(10, 10, "<start id='s0' x='1' y='1'/>"), 5);
        SimRobot robot = world.addRobot("r", Worlds.start(1, 1, 0), KoalaSpec.koala());
        goTo(robot, 8, 7);
        int steps = 0;
        while (robot.pose().distanceTo(8, 7) > 0.3 && steps < 3_000) {
            world.step();
            steps++;
        }
        double straight = Math.hypot(7, 6);
        assertTrue(robot.pose().distanceTo(8, 7) <= 0.3, "at " + robot.pose() + " after " + steps + " steps");
        assertTrue(steps * 0.02 >= straight / robot.spec().maxSpeed(), "no faster than top speed: " + steps + " steps");
        assertTrue(robot.odometry().travelled() >= straight - 0.4);
        assertTrue(robot.battery().level() < 1);
    }

    @Test
    void wheelSpeeds_rampWithinTheAccelerationLimitAndAreClamped() {
        SimWorld world = Worlds.world(Worlds.arena(10, 10, "<start id='s0' x='1' y='1'/>"), 5);
        SimRobot robot = world.addRobot("r", Worlds.start(1, 5, 0), KoalaSpec.koala().withOdometryNoise(0));
        robot.drive().setWheelSpeeds(5, 5);
        double dt = 0.02;
        double accel = robot.spec().maxAcceleration();
        double x = robot.pose().x();
        world.step();
        assertEquals(accel * dt * dt, robot.pose().x() - x, 1e-9, "first step: one acceleration increment");
        for (int i = 0; i < 100; i++) {
            world.step();
        }
        double before = robot.pose().x();
        world.step();
        assertEquals(robot.spec().maxSpeed() * dt, robot.pose().x() - before, 1e-9, "clamped at top speed");
        assertEquals(robot.pose().x(), robot.odometry().pose().x(), 1e-9, "noise-free odometry follows the body");
    }

    /**
     * A robot whose drive is dead stays a dynamic body of the robot's mass: its own drive holds it
     * still (its velocities are set to zero each step), but a teammate driving into it moves it in
     * the contact, about half the pusher's speed. So a dead robot in a doorway is an obstacle a
     * team could push aside, not a wall.
     */
    @Test
    void aDisabledRobot_staysPutAlone_butATeammateDrivingIntoItPushesItAlong() {
        SimWorld world = Worlds.world(Worlds.arena(10, 10, "<start id='s0' x='1' y='1'/>"), 5);
        SimRobot dead = world.addRobot("dead", Worlds.start(5, 5, 90), KoalaSpec.koala());
        SimRobot pusher = world.addRobot("pusher", Worlds.start(3, 5, 0), KoalaSpec.koala());
        dead.disable("battery");
        for (int i = 0; i < 250; i++) {
            world.step();
        }
        assertEquals(5, dead.pose().x(), 1e-9, "alone it does not move");
        goTo(pusher, 7, 5);
        for (int i = 0; i < 1_500; i++) {
            world.step();
        }
        assertTrue(dead.pose().x() > 5.5, "pushed along in 30 s: " + dead.pose());
        assertTrue(pusher.pose().x() > 5.3, "the pusher followed it: " + pusher.pose());
        assertEquals(5, dead.pose().y(), 0.2, "pushed along the pusher's line: " + dead.pose());
    }
}
