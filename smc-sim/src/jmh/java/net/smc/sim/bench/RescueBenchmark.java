package net.smc.sim.bench;

import java.io.ByteArrayOutputStream;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;

import net.smc.sim.render.GifRecorder;
import net.smc.sim.scenario.RescueScenario;
import org.openjdk.jmh.annotations.AuxCounters;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.infra.BenchmarkParams;

/**
 * The whole rescue of a wounded soldier ({@link RescueScenario}, as {@code smc demo rescue} runs
 * it: real signatures, the world's radio), headless, from loading its files to the end of the
 * mission; with {@code film=true} the GIF is recorded as the run goes and written (to memory) at
 * the end, as the demo does. The score is the wall time of one run (single shot; seed 1 + the
 * iteration). Secondary results, means over the iterations: {@code simulatedPerWall}, mission
 * seconds per wall second of the run; {@code simulatedPerCpu}, mission seconds per CPU second of
 * every thread of the process during the run (the film's encoder, the compiler and the garbage
 * collector included), what the run costs whatever else the machine is doing;
 * {@code simulatedPerThreadCpu}, mission seconds per CPU second of the thread that simulates (the
 * world, the cells, their signatures), the simulation itself without the JIT compiler, the garbage
 * collector or the film's encoder.
 *
 * <p>{@code rescue} runs with the JVM's default JIT (C1 then C2); {@code rescueC1} with the JIT
 * stopped at C1, as {@code ./gradlew demo} runs it: in a run of seconds the C2 compiler costs more
 * CPU than it saves.
 *
 * <pre>./gradlew :smc-sim:jmh -PjmhArgs='-wi 3 -i 5 RescueBenchmark'</pre>
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.SingleShotTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
@Fork(value = 1, jvmArgsAppend = {"-Xmx2g", "-Djava.awt.headless=true"})
public class RescueBenchmark {
    private static final ThreadMXBean THREADS = ManagementFactory.getThreadMXBean();

    @Param({"false", "true"})
    public boolean film;

    private Path project;
    private long seed;

    /**
     * What one run covered. JMH adds such counters up over the measurement iterations, so each
     * iteration's value is divided by their number: the result is the mean.
     */
    @State(Scope.Thread)
    @AuxCounters(AuxCounters.Type.EVENTS)
    public static class Rate {
        public double simulatedPerWall;
        public double simulatedPerCpu;
        public double simulatedPerThreadCpu;
        private int iterations;

        @Setup(Level.Trial)
        public void count(BenchmarkParams params) {
            iterations = Math.max(1, params.getMeasurement().getCount());
        }
    }

    @Setup(Level.Trial)
    public void find() {
        project = Path.of("").toAbsolutePath();
        if (!Files.isDirectory(project.resolve("missions"))) {
            project = project.getParent();
        }
    }

    @Benchmark
    public long rescue(Rate rate) throws Exception {
        return run(rate);
    }

    @Benchmark
    @Fork(value = 1, jvmArgsAppend = {"-Xmx2g", "-Djava.awt.headless=true", "-XX:TieredStopAtLevel=1"})
    public long rescueC1(Rate rate) throws Exception {
        return run(rate);
    }

    private long run(Rate rate) throws Exception {
        long wall = System.nanoTime();
        long cpu = processCpuNanos();
        long threadCpu = THREADS.getCurrentThreadCpuTime();
        RescueScenario.Settings settings = RescueScenario.Settings.of(1 + seed++);
        if (film) {
            settings = settings.withFilm(GifRecorder.Settings.defaults());
        }
        RescueScenario rescue = RescueScenario.load(project, settings, row -> { });
        RescueScenario.Outcome outcome = rescue.run();
        if (!outcome.succeeded()) {
            throw new IllegalStateException("the rescue failed: " + outcome.reason());
        }
        long size = 0;
        if (film) {
            ByteArrayOutputStream gif = new ByteArrayOutputStream();
            rescue.film().orElseThrow().write(gif);
            size = gif.size();
        }
        double mission = outcome.missionMillis() / 1e3;
        rate.simulatedPerWall += mission / ((System.nanoTime() - wall) / 1e9) / rate.iterations;
        rate.simulatedPerCpu += mission / ((processCpuNanos() - cpu) / 1e9) / rate.iterations;
        rate.simulatedPerThreadCpu += mission / ((THREADS.getCurrentThreadCpuTime() - threadCpu) / 1e9) / rate.iterations;
        return outcome.missionMillis() + size;
    }

    private static long processCpuNanos() {
        if (ManagementFactory.getOperatingSystemMXBean() instanceof com.sun.management.OperatingSystemMXBean os) {
            return os.getProcessCpuTime();
        }
        return THREADS.getCurrentThreadCpuTime();
    }
}
