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
import org.openjdk.jmh.infra.BenchmarkParams;

/**
 * Idle cells: a {@link ScaledTeam} of {@code vehicles} vehicles, formed and left 5 simulated
 * seconds to settle, then run one simulated second per operation, invariants checked every 50 ms.
 * The score, operations per wall second, is simulated seconds per wall second; with
 * {@code invariants=false} the harness's checks are off and the score is what the cells themselves
 * cost. Secondary results (means over the iterations),
 * independent of the machine: {@code bytesPerVehicleSecond} and
 * {@code datagramsPerVehicleSecond}, what each vehicle sends in the steady state (heartbeats and
 * their answers; a broadcast counted once, bytes as the cells hand them to the simulated network,
 * sealed by its ideal authentication), and {@code wireBytesPerVehicleSecond}, the same datagrams
 * in the envelopes the real security layer gives them (what a radio would carry).
 * Simulation speed during formation is {@link FormationBenchmark}'s {@code simulatedPerWall}.
 *
 * <pre>./gradlew :smc-sim:jmh -PjmhArgs='-wi 1 -i 3 SimulationSpeedBenchmark'</pre>
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.Throughput)
@OutputTimeUnit(TimeUnit.SECONDS)
@Fork(value = 1, jvmArgsAppend = {"-Xmx3g", "-Xss8m"})
public class SimulationSpeedBenchmark {
    @Param({"10", "100", "1000"})
    public int vehicles;

    /** Whether the harness checks the invariants every 50 ms ({@code false}: the cells' own cost). */
    @Param({"true", "false"})
    public boolean invariants;

    private ScaledTeam team;

    /**
     * Steady-state traffic since the iteration began. JMH adds such counters up over the
     * measurement iterations, so each value is divided by their number: the result is the mean.
     */
    @State(Scope.Thread)
    @AuxCounters(AuxCounters.Type.EVENTS)
    public static class Traffic {
        public double bytesPerVehicleSecond;
        /** The same bytes in the envelopes a real security layer gives them ({@link ScaledTeam#wireBytes}). */
        public double wireBytesPerVehicleSecond;
        public double datagramsPerVehicleSecond;
        long startMillis = -1;
        long startBytes;
        long startWireBytes;
        long startDatagrams;
        private int iterations;

        @Setup(Level.Trial)
        public void count(BenchmarkParams params) {
            iterations = Math.max(1, params.getMeasurement().getCount());
        }

        void update(ScaledTeam team) {
            if (startMillis < 0) {
                startMillis = team.sim.nowMillis();
                startBytes = team.bytes();
                startWireBytes = team.wireBytes();
                startDatagrams = team.datagrams();
                return;
            }
            double vehicleSeconds = team.size * (team.sim.nowMillis() - startMillis) / 1e3 * iterations;
            bytesPerVehicleSecond = (team.bytes() - startBytes) / vehicleSeconds;
            wireBytesPerVehicleSecond = (team.wireBytes() - startWireBytes) / vehicleSeconds;
            datagramsPerVehicleSecond = (team.datagrams() - startDatagrams) / vehicleSeconds;
        }

        @Setup(Level.Iteration)
        public void reset() {
            startMillis = -1;
        }
    }

    @Setup(Level.Trial)
    public void form() {
        team = new ScaledTeam(vehicles, 1, invariants);
        if (!team.form()) {
            throw new IllegalStateException(vehicles + " vehicles did not form within "
                    + ScaledTeam.FORMATION_LIMIT_MILLIS + " simulated ms (" + team.acceptedSeats() + " seats accepted)");
        }
        team.sim.run(5_000);
    }

    @Benchmark
    public long idleSecond(Traffic traffic) {
        traffic.update(team);
        team.sim.run(1_000);
        traffic.update(team);
        return team.sim.nowMillis();
    }
}
