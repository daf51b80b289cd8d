package net.smc.sim.render;

import java.util.ArrayDeque;
import java.util.Deque;
import java.util.LinkedHashMap;
import java.util.Map;

import net.smc.core.transport.sim.SimulationScheduler;
import net.smc.sim.hardware.Pose;
import net.smc.sim.robot.SimRobot;
import net.smc.sim.arena.ArenaException;
import net.smc.sim.arena.ArenaReader;
import net.smc.sim.world.SimWorld;
import net.smc.sim.world.WorldStepListener;
import net.smc.sim.world.Worlds;

/**
 * A test driver in the spirit of the paper's Fig. 7, without cells: on the rescue arena, r1 (the
 * surveyor) drives straight at the soldier until the hazard disables it; then r2 (the aggregator)
 * becomes the surveyor and goes round a zone about r1's last position to the soldier. Its
 * recorders (trajectories, GIF, timeline) and scene are the ones a scenario would feed.
 */
final class RescueRun {
    static final double SOLDIER_X = 11;
    static final double SOLDIER_Y = 4;
    static final double AVOID_RADIUS = 1.8;

    final SimulationScheduler scheduler = new SimulationScheduler();
    final SimWorld world;
    final SimRobot r1;
    final SimRobot r2;
    final Map<String, String> roles = new LinkedHashMap<>();
    final TrajectoryRecorder tracks = new TrajectoryRecorder(5);
    final Scene scene = new Scene("Rescue: surveyor stopped by the hazard, replaced (cf. Fig. 7)");
    final Timeline timeline = new Timeline();
    final GifRecorder gif;
    boolean reached;

    RescueRun(GifRecorder.Settings film) {
        try {
            world = SimWorld.builder(ArenaReader.read(Worlds.worldFile("rescue.xml")), scheduler).seed(7).build();
        } catch (ArenaException | java.io.IOException e) {
            throw new AssertionError(e.getMessage(), e);
        }
        r1 = world.addRobot("r1", "r1");
        r2 = world.addRobot("r2", "r2");
        roles.put("r1", "surveyor");
        roles.put("r2", "aggregator");
        scene.roles(RoleLabels.of(roles)).trajectories(tracks).caption("(iv) surveyor r1 heads for the soldier");
        timeline.record(0, "r1", "ASSIGNED", "surveyor", "iii").record(0, "r2", "ASSIGNED", "aggregator", "iii");
        world.addListener(tracks);
        gif = new GifRecorder(new WorldPainter(), scene, film);
        world.addListener(gif);
        world.addListener(new WorldStepListener() {
            @Override
            public void disabled(SimWorld w, SimRobot robot, String cause) {
                if (robot == r1) {
                    takeOver(robot, cause);
                }
            }
        });
        follow(r1, new double[][] {{SOLDIER_X - 0.5, SOLDIER_Y}});
        world.start();
    }

    /** Step (v): r2 becomes the surveyor, told r1's last position, and goes round it. */
    private void takeOver(SimRobot stopped, String cause) {
        long now = scheduler.nowMillis();
        double sx = stopped.x();
        double sy = stopped.y();
        timeline.record(now, "r1", "DISABLED", cause + " at (" + round(sx) + ", " + round(sy) + ")", "iv");
        timeline.record(now + 1_500, "r2", "ASSIGNED", "surveyor, avoid \"r1's last position\"", "v");
        roles.put("r1", "surveyor (lost)");
        roles.put("r2", "surveyor");
        scene.caption("(v)-(vi) r2 takes over and avoids the zone").mark(new Mark.AvoidedZone(sx, sy, AVOID_RADIUS, "avoided zone"));
        follow(r2, new double[][] {{sx - 1.0, sy - AVOID_RADIUS - 0.4}, {sx + 2.2, sy - AVOID_RADIUS - 0.4},
            {SOLDIER_X - 0.55, SOLDIER_Y - 0.1}});
    }

    /** Runs until r2 reaches the soldier, or {@code limitMillis} of mission time pass. */
    void run(long limitMillis) {
        scheduler.runUntil(() -> reached, limitMillis);
        gif.capture(world);
    }

    /** Steers {@code robot} through the waypoints by its odometry; stops within 8 cm of the last. */
    private void follow(SimRobot robot, double[][] waypoints) {
        Deque<double[]> left = new ArrayDeque<>(java.util.List.of(waypoints));
        robot.control(this, (time, dt) -> {
            Pose p = robot.odometry().pose();
            double[] goal = left.peek();
            if (goal == null) {
                robot.drive().stop();
                return;
            }
            double distance = p.distanceTo(goal[0], goal[1]);
            if (distance < (left.size() == 1 ? 0.08 : 0.2)) {
                left.pop();
                if (left.isEmpty() && robot == r2) {
                    reached = true;
                    scene.caption("(vii) r2 reached the soldier");
                    timeline.record(scheduler.nowMillis(), "r2", "REACHED", "soldier", "vii");
                }
                return;
            }
            double error = Math.IEEEremainder(Math.atan2(goal[1] - p.y(), goal[0] - p.x()) - p.heading(), 2 * Math.PI);
            double forward = Math.min(0.4, distance) * Math.max(0, Math.cos(error));
            double turn = 0.5 * error;
            robot.drive().setWheelSpeeds(forward - turn, forward + turn);
        });
    }

    private static String round(double v) {
        return String.format(java.util.Locale.ROOT, "%.2f", v);
    }
}
