package net.smc.sim.bench;

import java.util.concurrent.TimeUnit;

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
import org.openjdk.jmh.annotations.Timeout;
import org.openjdk.jmh.infra.BenchmarkParams;

/**
 * Formation time versus team size: a {@link ScaledTeam} of {@code vehicles} vehicles (one role
 * each, a management tree of depth 4) starts at once and runs until every seat is accepted. The
 * score is the wall time of one formation (single shot: the team is built, not started, before the
 * clock starts; every iteration a new team and seed). Secondary results, per formation:
 * {@code simulatedMs}, the simulated time from the commander's start to the last seat accepted;
 * {@code simulatedPerWall}, simulated seconds per wall second while forming; {@code unformed}, 1
 * when the team did not form within 600 simulated seconds (means over the iterations; the
 * per-iteration lines show them divided by the number of iterations).
 *
 * <pre>./gradlew :smc-sim:jmh -PjmhArgs='-wi 1 -i 3 FormationBenchmark -p vehicles=10,100,1000'
 * ./gradlew :smc-sim:jmh -PjmhArgs='-wi 0 -i 1 FormationBenchmark -p vehicles=10000'</pre>
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.SingleShotTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
@Fork(value = 1, jvmArgsAppend = {"-Xmx8g", "-Xss8m"})
@Timeout(time = 60, timeUnit = TimeUnit.MINUTES)   // 10,000 vehicles take minutes on a shared 2-core machine
public class FormationBenchmark {
    @Param({"10", "100", "1000", "10000"})
    public int vehicles;

    /** Whether the harness checks the invariants every 50 ms ({@code false}: the cells' own cost). */
    @Param({"true"})
    public boolean invariants;

    private ScaledTeam team;
    private long seed;

    /**
     * What one formation took in the simulation. JMH adds such counters up over the measurement
     * iterations, so each iteration's value is divided by their number: the result is the mean.
     */
    @State(Scope.Thread)
    @AuxCounters(AuxCounters.Type.EVENTS)
    public static class Simulated {
        public double simulatedMs;
        public double simulatedPerWall;
        public double unformed;
        private int iterations;

        @Setup(Level.Trial)
        public void count(BenchmarkParams params) {
            iterations = Math.max(1, params.getMeasurement().getCount());
        }
    }

    @Setup(Level.Invocation)
    public void build() {
        team = new ScaledTeam(vehicles, ++seed, invariants);
    }

    @Benchmark
    public boolean form(Simulated out) {
        long t0 = System.nanoTime();
        boolean formed = team.form();
        double wallMs = (System.nanoTime() - t0) / 1e6;
        out.simulatedMs = (formed ? team.formationMillis() : Double.NaN) / out.iterations;
        out.simulatedPerWall = team.sim.nowMillis() / wallMs / out.iterations;
        out.unformed = (formed ? 0 : 1.0) / out.iterations;
        return formed;
    }
}
