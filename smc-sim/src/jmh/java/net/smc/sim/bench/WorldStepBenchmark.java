package net.smc.sim.bench;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

import net.smc.core.transport.sim.SimulationScheduler;
import net.smc.sim.robot.KoalaSpec;
import net.smc.sim.robot.SimRobot;
import net.smc.sim.arena.Arena;
import net.smc.sim.arena.ArenaReader;
import net.smc.sim.world.SimWorld;
import org.dyn4j.geometry.AABB;
import org.openjdk.jmh.annotations.AuxCounters;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.infra.BenchmarkParams;

/**
 * One 20 ms world step, run by the scheduler, with every robot's control loop reading all of its
 * sensors (16 infrared rays, the camera, the chemical sensor, the radio's neighbour table) and
 * wandering. Throughput in steps per second times 0.02 is simulated seconds per wall second:
 * {@code rescue} has the paper's 3 robots, {@code house} 50 robots in the house arena, spread
 * through its rooms (a steady state of robots driving about; {@code layout=lobby} packs them into
 * the lobby instead, a pile-up that lasts the whole run). The secondary result
 * {@code simulatedPerCpu} is simulated seconds per CPU second of the benchmark thread: what the
 * simulation costs, whatever else the machine is doing ({@link CpuRate}).
 *
 * <pre>./gradlew :smc-sim:jmh -PjmhArgs='-f 1 -wi 2 -i 3 -w 1s -r 1s WorldStepBenchmark'</pre>
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.Throughput)
@OutputTimeUnit(TimeUnit.SECONDS)
public class WorldStepBenchmark {
    @Param({"rescue", "house"})
    public String arena;

    /** Where the house's robots start: {@code spread} through the rooms, or packed in the {@code lobby}. */
    @Param({"spread"})
    public String layout;

    private SimulationScheduler scheduler;
    private SimWorld world;
    private double sink;

    @Setup(Level.Trial)
    public void setUp() throws Exception {
        Path dir = Path.of("missions/worlds");
        if (!Files.isDirectory(dir)) {
            dir = Path.of("../missions/worlds");
        }
        Arena a = ArenaReader.read(dir.resolve(arena + ".xml"));
        scheduler = new SimulationScheduler();
        world = SimWorld.builder(a, scheduler).seed(17).build();
        if (arena.equals("rescue")) {
            for (String id : new String[] {"r1", "r2", "r3"}) {
                wander(world.addRobot(id, id));
            }
        } else if (layout.equals("lobby")) {
            // 50 robots on a 0.6 m grid in the lobby (x 0-4), clear of its pillar at (2, 10)
            int n = 0;
            for (int row = 0; row < 22 && n < 50; row++) {
                for (int col = 0; col < 6 && n < 50; col++) {
                    double x = 0.5 + 0.6 * col;
                    double y = 0.5 + 0.6 * row;
                    if (Math.hypot(x - 2, y - 10) > 0.8) {
                        wander(world.addRobot("r" + n++, new Arena.Start("g", x, y, 0), KoalaSpec.koala()));
                    }
                }
            }
        } else {
            // 50 robots spread through the house: on free points of a 1 m grid, away from the hazards
            // that disable, evenly chosen and facing all ways
            List<double[]> free = new ArrayList<>();
            for (double y = 0.5; y < a.height(); y++) {
                for (double x = 0.5; x < a.width(); x++) {
                    if (free(world, a, x, y)) {
                        free.add(new double[] {x, y});
                    }
                }
            }
            for (int n = 0; n < 50; n++) {
                double[] at = free.get(n * free.size() / 50);
                wander(world.addRobot("r" + n, new Arena.Start("g", at[0], at[1], 2.4 * n), KoalaSpec.koala()));
            }
        }
        world.start();
        scheduler.runFor(1_000);
    }

    private static boolean free(SimWorld world, Arena a, double x, double y) {
        for (Arena.Hazard h : a.hazards()) {
            if (h.disables() && Math.hypot(x - h.x(), y - h.y()) < h.effect() + 0.5) {
                return false;
            }
        }
        return world.physics().detect(new AABB(x - 0.3, y - 0.3, x + 0.3, y + 0.3), null).isEmpty();
    }

    private void wander(SimRobot robot) {
        robot.control(robot, (time, dt) -> {
            double[] ir = robot.proximity().read();
            double left = ir[0] + ir[1] + ir[2] + ir[3];
            double right = ir[12] + ir[13] + ir[14] + ir[15];
            sink += robot.camera().look().size() + robot.chemical().sense().size()
                    + robot.radio().neighbours().size() + robot.odometry().pose().x() + robot.battery().level();
            double turn = (left - right) * 1.5;
            double ahead = Math.min(ir[0], ir[15]) < 0.1 ? -0.1 : 0.4;
            robot.drive().setWheelSpeeds(ahead - turn, ahead + turn);
        });
    }

    @Benchmark
    public double step(CpuRate rate) {
        scheduler.runFor(world.stepMillis());
        rate.ran(world.stepMillis());
        return sink;
    }

    /**
     * Simulated seconds per CPU second of the thread that runs the simulation, over each
     * measurement iteration. JMH adds such counters up over the iterations, so each iteration's
     * value is divided by their number: the result is the mean.
     */
    @State(Scope.Thread)
    @AuxCounters(AuxCounters.Type.EVENTS)
    public static class CpuRate {
        private static final ThreadMXBean THREADS = ManagementFactory.getThreadMXBean();
        public double simulatedPerCpu;
        private long simulatedMillis;
        private long startNanos;
        private int iterations;

        @Setup(Level.Trial)
        public void count(BenchmarkParams params) {
            iterations = Math.max(1, params.getMeasurement().getCount());
        }

        @Setup(Level.Iteration)
        public void reset() {
            simulatedMillis = 0;
            startNanos = THREADS.getCurrentThreadCpuTime();
        }

        /** Called after each operation with the simulated time it covered. */
        public void ran(long millis) {
            simulatedMillis += millis;
            long cpu = THREADS.getCurrentThreadCpuTime() - startNanos;
            if (cpu > 0) {
                simulatedPerCpu = simulatedMillis / 1e3 / (cpu / 1e9) / iterations;
            }
        }
    }
}
