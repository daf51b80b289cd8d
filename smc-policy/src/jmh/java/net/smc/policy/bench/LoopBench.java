package net.smc.policy.bench;

import java.math.BigDecimal;
import java.util.List;
import java.util.concurrent.TimeUnit;
import net.smc.policy.api.AuthMode;
import net.smc.policy.PolicyEngine;
import net.smc.policy.api.Diagnostic;
import net.smc.policy.RunResult;
import net.smc.policy.runtime.PHash;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OperationsPerInvocation;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.TearDown;
import org.openjdk.jmh.annotations.Warmup;

/**
 * Goal: the interpreter runs {@code 1000000 do: [:i | h at: "k" put: i + 1]} at 150 ns or less
 * per iteration. One invocation runs the whole unit ({@code cell.run}, parsing included: one
 * line); the score is per loop iteration. {@code body=empty} ({@code [:i | i]}) is the baseline:
 * the cost of the loop and the block call alone.
 */
@State(Scope.Thread)
@Fork(2)
@Warmup(iterations = 2, time = 2)
@Measurement(iterations = 3, time = 2)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
public class LoopBench {
    private static final int ITERATIONS = 1_000_000;

    @Param({"atPut", "empty"})
    String body;

    private final List<Diagnostic> errors = Bench.errors();
    private PolicyEngine cell;
    private String text;

    @Setup(Level.Trial)
    public void setUp() {
        cell = Bench.cell(AuthMode.OFF, errors);
        String block = body.equals("atPut") ? "h at: \"k\" put: i + 1" : "i";
        text = "h := #() asHash. " + ITERATIONS + " do: [:i | " + block + "]. h";
        check(cell.run("loop", text));
    }

    @Benchmark
    @OperationsPerInvocation(ITERATIONS)
    public RunResult loop() {
        return cell.run("loop", text);
    }

    @TearDown(Level.Trial)
    public void tearDown() {
        check(cell.run("loop", text));
    }

    private void check(RunResult result) {
        Bench.check(result.ok() && errors.isEmpty(), "loop: " + result + " " + errors);
        PHash h = (PHash) result.value();
        Bench.check(body.equals("atPut") ? BigDecimal.valueOf(ITERATIONS).equals(h.get("k")) : h.size() == 0, "h: " + h);
    }
}
