package net.smc.policy.bench;

import java.math.BigDecimal;
import java.util.List;
import java.util.concurrent.TimeUnit;
import net.smc.policy.api.AuthMode;
import net.smc.policy.PolicyEngine;
import net.smc.policy.api.Diagnostic;
import net.smc.policy.RunResult;
import net.smc.policy.lang.Unit;
import net.smc.policy.runtime.Domain;
import net.smc.policy.runtime.PHash;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.TearDown;
import org.openjdk.jmh.annotations.Warmup;

/**
 * Goal: parsing and loading 1,000 obligation policies from text (each made, given a template, a
 * condition block and an action block, activated, and stored in {@code root/policy}) takes 50 ms
 * or less. Each invocation gets a fresh cell that already holds the 1,000 templates, so only the
 * policies' parse and load is timed. {@code parseOnly} times the parse alone, to split the cost;
 * {@code policies=250} checks that the cost per policy does not grow with the count.
 */
@State(Scope.Thread)
@Fork(2)
@Warmup(iterations = 2, time = 1)
@Measurement(iterations = 5, time = 1)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
public class LoadBench {
    @Param({"250", "1000"})
    int policies;

    private final List<Diagnostic> errors = Bench.errors();
    private String templates;
    private String text;
    private PolicyEngine cell;

    @Setup(Level.Trial)
    public void texts() {
        templates = Bench.templates("e", policies);
        text = "store := #() asHash. root at: \"store\" put: store.\n" + Bench.policies("p", "e", policies, "k");
    }

    @Setup(Level.Invocation)
    public void freshCell() {
        errors.clear();
        cell = Bench.cell(AuthMode.OFF, errors);
        Bench.run(cell, "templates", templates, errors);
    }

    @Benchmark
    public RunResult load() {
        return cell.run("policies", text);
    }

    @Benchmark
    public Unit parseOnly() {
        return cell.runtime().parse("policies", text, null);
    }

    /** Not timed: after {@code load}, every policy is stored and live. */
    @TearDown(Level.Invocation)
    public void check() {
        Bench.check(errors.isEmpty(), "errors: " + errors);
        Domain stored = (Domain) cell.resolve("root/policy");
        if (stored.entries().isEmpty()) {
            return;   // parseOnly
        }
        Bench.check(stored.entries().size() == policies, "stored policies: " + stored.entries().size());
        PHash store = (PHash) cell.resolve("root/store");
        Bench.check(cell.raise("root/event/e" + (policies - 1), "x", BigDecimal.valueOf(9))
                && BigDecimal.valueOf(9).equals(store.get("k")) && errors.isEmpty(), "last policy fired: " + store + errors);
    }
}
