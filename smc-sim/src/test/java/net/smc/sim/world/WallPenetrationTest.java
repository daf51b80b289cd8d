package net.smc.sim.world;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;

import net.smc.sim.arena.Arena;
import net.smc.sim.hardware.Pose;
import net.smc.sim.robot.KoalaSpec;
import net.smc.sim.robot.SimRobot;
import org.junit.jupiter.api.Test;

class WallPenetrationTest {
    /** dyn4j's allowed penetration is 5 mm; a body that passes through a wall would go far deeper. */
    private static final double TOLERANCE = 0.02;

    @Test
    void robotsPushingIntoWalls_neverPenetrateThemOver100kSteps() {
        Arena arena = Worlds.arena(5, 4, "<start id='s0' x='0.5' y='0.5'/>"
                + "<wall x1='2.5' y1='0' x2='2.5' y2='2.6'/><wall x1='1' y1='3' x2='4' y2='3.2' thickness='0.05'/>"
                + "<box x='4' y='1' width='0.5' height='0.5' angle='20'/>");
        SimWorld world = Worlds.world(arena, 11);
        List<SimRobot> robots = new ArrayList<>();
        robots.add(world.addRobot("a", Worlds.start(1, 1, 30), KoalaSpec.koala()));
        robots.add(world.addRobot("b", Worlds.start(3.5, 2, 120), KoalaSpec.koala()));
        robots.add(world.addRobot("c", Worlds.start(1.5, 2.5, -60), KoalaSpec.koala()));
        SplittableRandom random = new SplittableRandom(11);
        for (SimRobot robot : robots) {
            // full speed ahead, and every few seconds a new random turn: it spends most of its time against walls
            double[] wheels = {robot.spec().maxSpeed(), robot.spec().maxSpeed()};
            robot.control(this, (time, dt) -> {
                if (random.nextDouble() < 0.01) {
                    double turn = random.nextDouble(-0.6, 0.6);
                    wheels[0] = robot.spec().maxSpeed() - turn;
                    wheels[1] = robot.spec().maxSpeed() + turn;
                }
                robot.drive().setWheelSpeeds(wheels[0], wheels[1]);
            });
        }
        List<double[]> walls = rectangles(arena);
        double[] deepest = new double[1];
        world.addListener(new WorldStepListener() {
            @Override
            public void stepped(SimWorld w) {
                for (SimRobot robot : w.robots()) {
                    double depth = penetration(robot, walls);
                    deepest[0] = Math.max(deepest[0], depth);
                    assertTrue(depth < TOLERANCE, robot + " is " + depth + " m into a wall at step " + w.steps()
                            + ", pose " + robot.pose());
                }
            }
        });
        for (int i = 0; i < 100_000; i++) {
            world.step();
        }
        assertTrue(deepest[0] > 0, "the robots did touch the walls (deepest contact " + deepest[0] + " m)");
        for (SimRobot robot : robots) {
            assertTrue(robot.odometry().travelled() > 100, robot + " kept moving: " + robot.odometry().travelled());
        }
    }

    /** Each solid rectangle as {cx, cy, halfWidth, halfHeight, angle}: fence, walls, boxes. */
    private static List<double[]> rectangles(Arena arena) {
        List<double[]> out = new ArrayList<>();
        double w = arena.width();
        double h = arena.height();
        out.add(new double[] {w / 2, -0.1, w, 0.1, 0});
        out.add(new double[] {w / 2, h + 0.1, w, 0.1, 0});
        out.add(new double[] {-0.1, h / 2, 0.1, h, 0});
        out.add(new double[] {w + 0.1, h / 2, 0.1, h, 0});
        for (Arena.Wall wall : arena.walls()) {
            out.add(new double[] {(wall.x1() + wall.x2()) / 2, (wall.y1() + wall.y2()) / 2,
                (wall.length() + wall.thickness()) / 2, wall.thickness() / 2,
                Math.atan2(wall.y2() - wall.y1(), wall.x2() - wall.x1())});
        }
        for (Arena.Box box : arena.boxes()) {
            out.add(new double[] {box.x(), box.y(), box.width() / 2, box.height() / 2, box.angle()});
        }
        return out;
    }

    /** How deep a corner of either rectangle lies inside the other, deepest over all walls. */
    private static double penetration(SimRobot robot, List<double[]> walls) {
        Pose p = robot.pose();
        double[] body = {p.x(), p.y(), robot.spec().length() / 2, robot.spec().width() / 2, p.heading()};
        double deepest = 0;
        for (double[] wall : walls) {
            deepest = Math.max(deepest, Math.max(cornersInside(body, wall), cornersInside(wall, body)));
        }
        return deepest;
    }

    private static double cornersInside(double[] a, double[] b) {
        double deepest = 0;
        double c = Math.cos(a[4]);
        double s = Math.sin(a[4]);
        double bc = Math.cos(b[4]);
        double bs = Math.sin(b[4]);
        for (int sx = -1; sx <= 1; sx += 2) {
            for (int sy = -1; sy <= 1; sy += 2) {
                double x = a[0] + c * sx * a[2] - s * sy * a[3] - b[0];
                double y = a[1] + s * sx * a[2] + c * sy * a[3] - b[1];
                double lx = bc * x + bs * y;
                double ly = -bs * x + bc * y;
                deepest = Math.max(deepest, Math.min(b[2] - Math.abs(lx), b[3] - Math.abs(ly)));
            }
        }
        return deepest;
    }
}
