package net.smc.policy.bench;

import java.math.BigDecimal;
import java.util.List;
import java.util.concurrent.TimeUnit;
import net.smc.policy.api.AuthMode;
import net.smc.policy.PolicyEngine;
import net.smc.policy.api.Diagnostic;
import net.smc.policy.runtime.EventTemplate;
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
 * Goal: raising an event from Java through one active obligation policy
 * ({@code [:level | level > 5]} then {@code store at: "k" put: level}) runs at 2,000,000
 * events/s or more on one core, and 1,000 other active policies on other templates (all attached
 * to root) do not slow it down. {@code level=3} (condition false, no action) is a reference.
 */
@State(Scope.Thread)
@Fork(2)
@Warmup(iterations = 2, time = 1)
@Measurement(iterations = 5, time = 1)
@BenchmarkMode(Mode.Throughput)
@OutputTimeUnit(TimeUnit.SECONDS)
public class EventBench {
    /** Other active policies, each on a template of its own: 0 is the baseline. */
    @Param({"0", "1000"})
    int otherPolicies;

    /**
     * Control: {@code true} loads the other policies into a throwaway cell instead (the same code
     * runs during setup, so the JIT sees the same profile, but the measured cell has none of them).
     */
    @Param({"false"})
    boolean othersElsewhere;

    /** The event's level: 7 runs the action, 3 stops at the condition. */
    @Param({"7", "3"})
    int level;

    private final List<Diagnostic> errors = Bench.errors();
    private PolicyEngine cell;
    private EventTemplate alarm;
    private BigDecimal value;
    private PHash store;

    @Setup(Level.Trial)
    public void setUp() {
        cell = Bench.cell(AuthMode.OFF, errors);
        // The other policies first, so the measured one is attached last.
        PolicyEngine othersCell = othersElsewhere ? Bench.cell(AuthMode.OFF, errors) : cell;
        Bench.run(othersCell, "others", "store := #() asHash. root at: \"others\" put: store.\n"
                + Bench.templates("o", otherPolicies) + Bench.policies("o", "o", otherPolicies, "o"), errors);
        Bench.run(cell, "boot", """
                root/event at: "alarm" put: (root/factory/event create: #("name" "level")).
                store := #() asHash.
                root at: "store" put: store.
                p := root/factory/ecapolicy create.
                p event: root/event/alarm; condition: [:level | level > 5]; action: [:level | store at: "k" put: level].
                p active: true.
                root/policy at: "alarm" put: p.
                """, errors);
        cell.endBoot();
        alarm = (EventTemplate) cell.template("root/event/alarm");
        store = (PHash) cell.resolve("root/store");
        value = BigDecimal.valueOf(level);

        // The measured policy fires, or not, as its condition says ...
        Bench.check(cell.raise(alarm, "boiler", value) && errors.isEmpty(), "raise: " + errors);
        Bench.check(store.containsKey("k") == (level > 5), "store after one event: " + store);
        // ... and the other policies are live (each reacts to its own template only).
        if (otherPolicies > 0 && !othersElsewhere) {
            PHash others = (PHash) cell.resolve("root/others");
            cell.raise("root/event/o" + (otherPolicies / 2), "x", BigDecimal.valueOf(9));
            Bench.check(others.size() == 1 && BigDecimal.valueOf(9).equals(others.get("o")), "others: " + others);
        }
        store.removeAll();
    }

    @Benchmark
    public boolean raise() {
        return cell.raise(alarm, "boiler", value);
    }

    @TearDown(Level.Trial)
    public void tearDown() {
        Bench.check(errors.isEmpty(), "errors while measuring: " + errors);
        Bench.check(level > 5 ? value.equals(store.get("k")) : store.size() == 0, "store after measuring: " + store);
    }
}
