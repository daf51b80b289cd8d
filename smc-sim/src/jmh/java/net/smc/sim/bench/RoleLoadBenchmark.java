package net.smc.sim.bench;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;

import net.smc.sim.experiment.MissionGenerator;
import net.smc.sim.experiment.RoleLoadWork;
import net.smc.sim.experiment.TreeShape;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;

/**
 * A vehicle taking a manager's role of the set-up time experiment's mission (20 roles, depth 4):
 * its booted engine loads the role's downloaded role-mission and authorisations, and withdraws them
 * again ({@link RoleLoadWork}). What the experiment's {@code Calibration} charges per byte of policy
 * reply, timed here to find where a role load's time goes.
 *
 * <pre>./gradlew :smc-sim:jmh -PjmhArgs='RoleLoadBenchmark'</pre>
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MICROSECONDS)
public class RoleLoadBenchmark {
    private RoleLoadWork work;

    @Setup
    public void setUp() throws Exception {
        Path boot = Path.of("policies/boot/events.p2");
        if (!Files.isRegularFile(boot)) {
            boot = Path.of("../policies/boot/events.p2");
        }
        Path dir = Files.createTempDirectory("role-load-bench");
        work = new RoleLoadWork(boot, MissionGenerator.write(TreeShape.of(20, 4), dir, boot));
    }

    @Benchmark
    public void loadAndWithdraw() throws Exception {
        work.loadAndWithdraw();
    }
}
