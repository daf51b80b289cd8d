package net.smc.policy;

import net.smc.policy.api.Limits;
import net.smc.policy.api.Diagnostic;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.Test;

/** The bounds of {@link Limits} on one run: errors reported, characters and elements built, time taken. */
class RunLimitsTest {
    private final List<Diagnostic> errors = new ArrayList<>();
    private final List<String> output = new ArrayList<>();

    private PolicyEngine cell(Limits limits) {
        return PolicyEngine.builder().limits(limits).errors(errors::add).output(output::add).build();
    }

    private List<String> messages() {
        return errors.stream().map(Diagnostic::message).toList();
    }

    @Test
    void eventStorm_isCutAtItsFirstOverflowAndReportedOnce() {
        PolicyEngine cell = cell(Limits.DEFAULT.withMaxCallDepth(50));

        RunResult result = cell.run("storm.p2", """
                t := root/factory/event create: #().
                p := root/factory/ecapolicy create.
                root/policy at: "p" put: p.
                p event: t; action: [t create: #(). t create: #(). t create: #()]; active: true.
                t create: #().
                root print: "after".
                """);

        assertTrue(result.ok(), messages().toString());
        assertEquals(List.of("ObligationPolicy: unhandled action error: call depth limit of 50 exceeded"), messages());
        assertEquals(List.of("after"), output);
    }

    @Test
    void errorsBeyondThePerRunLimit_areCountedNotReported() {
        PolicyEngine cell = cell(Limits.DEFAULT.withMaxErrorsPerRun(3));

        RunResult result = cell.run("many.p2", """
                t := root/factory/event create: #().
                p := root/factory/ecapolicy create.
                p event: t; action: [nil frob]; active: true.
                #(1 2 3 4 5 6 7 8 9 10) do: [:i | t create: #()].
                """);

        assertEquals(4, errors.size(), messages().toString());
        assertEquals("7 more errors of this run suppressed (only the first 3 are reported)", messages().get(3));
        assertEquals(4, result.diagnostics().size(), "the run keeps only what it reported");
        errors.clear();
        cell.run("next.p2", "root/factory/event create: #(). nil frob.");
        assertEquals(1, errors.size(), "each run has its own count: " + messages());
    }

    @Test
    void errorsOfARaiseFromJava_areBoundedToo() {
        PolicyEngine cell = cell(Limits.DEFAULT.withMaxErrorsPerRun(2));
        cell.run("boot.p2", """
                root/event at: "e" put: (root/factory/event create: #()).
                #(1 2 3 4 5) do: [:i | root/factory/ecapolicy create event: root/event/e; action: [nil frob]; active: true].
                """);

        cell.raise("root/event/e");

        assertEquals(3, errors.size(), messages().toString());
        assertTrue(messages().get(2).startsWith("3 more errors of this run suppressed"), messages().toString());
    }

    @Test
    void buildingHugeStringsOneSendAtATime_endsAtTheBuiltLimit() {
        PolicyEngine cell = cell(Limits.DEFAULT.withMaxBuiltPerRun(100_000));

        RunResult result = cell.run("grow.p2", """
                h := #() asHash.
                h at: "s" put: "x" * 1000.
                [true] whileTrue: [(h at: "s") + "x"].
                """);

        assertEquals(RunResult.Status.RUNTIME_ERROR, result.status());
        assertEquals(List.of("built limit of 100000 characters and elements per run exceeded (by String +)"),
                messages());
    }

    @Test
    void bulkCopiesAndPrinting_countAgainstTheBuiltLimit() {
        PolicyEngine cell = cell(Limits.DEFAULT.withMaxBuiltPerRun(1_000));

        cell.run("copy.p2", """
                a := #(1 2 3 4 5 6 7 8 9 10).
                [true] whileTrue: [a addAll: a].
                """);
        cell.run("print.p2", """
                s := "y" * 100.
                [true] whileTrue: [root print: s].
                """);

        assertEquals(2, errors.size(), messages().toString());
        assertTrue(messages().get(0).endsWith("(by Array addAll:)"), messages().toString());
        assertTrue(messages().get(1).endsWith("(by print:)"), messages().toString());
        assertEquals(9, output.size(), "s * 100 took 100 of the 1000; the tenth print would pass the limit");
    }

    @Test
    void aRunLongerThanTheTimeLimitByTheInjectedClock_ends() {
        AtomicLong now = new AtomicLong();
        PolicyEngine cell = PolicyEngine.builder().limits(Limits.DEFAULT.withMaxRunMillis(5_000)).errors(errors::add)
                .clock(() -> now.addAndGet(1)).build();

        RunResult result = cell.run("spin.p2", "[true] whileTrue: [1].");

        assertEquals(RunResult.Status.RUNTIME_ERROR, result.status());
        assertEquals(1, errors.size(), messages().toString());
        assertTrue(messages().get(0).startsWith("time limit of 5000 ms per run exceeded"), messages().toString());
    }

    @Test
    void aClockThatDoesNotMove_neverTripsTheTimeLimit() {
        PolicyEngine cell = PolicyEngine.builder().limits(Limits.DEFAULT.withMaxRunMillis(1).withMaxSteps(100_000))
                .errors(errors::add).build();

        cell.run("spin.p2", "[true] whileTrue: [1].");

        assertEquals(List.of("step limit of 100000 sends exceeded"), messages());
    }

    @Test
    void limits_areValidated() {
        org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class,
                () -> Limits.DEFAULT.withMaxErrorsPerRun(0));
        org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class,
                () -> Limits.DEFAULT.withMaxBuiltPerRun(0));
        org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class,
                () -> Limits.DEFAULT.withMaxRunMillis(-1));
    }

    @Test
    void stop_endsAnEndlessLoopWithinTheCheckInterval_andNothingRunsAfter() {
        PolicyEngine[] cell = new PolicyEngine[1];
        cell[0] = PolicyEngine.builder().errors(errors::add).output(line -> {
            output.add(line);
            if (output.size() == 3) {
                cell[0].stop(143);   // as a signal handler would, here on the cell's own thread
            }
        }).build();

        RunResult result = cell[0].run("loop.p2", "[true] whileTrue: [root print: \"tick\"]. root print: \"after\".");

        assertEquals(RunResult.Status.EXITED, result.status());
        assertEquals(143, cell[0].exitStatus().orElseThrow());
        assertTrue(output.size() < 3 + Limits.CLOCK_CHECK_INTERVAL, "ended within the check interval: " + output.size());
        assertTrue(!output.contains("after"), "the rest of the unit does not run");
        assertEquals(List.of(), messages(), "a stop is not an error");
        assertEquals(RunResult.Status.EXITED, cell[0].run("next.p2", "root print: 1.").status());
    }

    /**
     * One number operation whose exact result would run to hundreds of millions of digits is
     * refused before it is worked out: no step or time limit can stop a single operation, and each
     * of these held the cell's thread for minutes (or without end) while BigDecimal wrote the digits.
     */
    @Test
    void aNumberOperationOnHugeExponents_isRefusedAtOnce() {
        PolicyEngine cell = cell(Limits.DEFAULT);
        List<String> overflowing = List.of("1e100000000 + 1", "1e-400000000 + 1", "1 - 1e400000000", "1 / 3e-400000000",
                "1e400000000 / 1", "0E-400000000 + 1");
        org.junit.jupiter.api.Assertions.assertTimeoutPreemptively(java.time.Duration.ofSeconds(20), () -> {
            for (String expression : overflowing) {
                errors.clear();
                cell.run("huge.p2", "root print: " + expression + ".");
                assertEquals(List.of("number overflow"), messages(), expression);
            }
            cell.run("random.p2", "root print: (1e400000000 random) < 1e400000000.");
            cell.run("tiny.p2", "root print: (1e-400000000 collect: [:i | i]) size. root print: 1e-400000000 random.");
            cell.run("zero.p2", "root print: (0E-20000 + 1E-20000) == 1E-20000. root print: (1E9999 + 1) > 0.");
            cell.run("loop.p2", "1e400000000 do: [:i | root print: i. i == 1 ifTrue: [root exit]].");
        });
        assertEquals(List.of("true", "1", "0", "true", "true", "0", "1"), output,
                "random of a huge number answers at once, a loop over a tiny one runs once, a sum with a zero or of"
                        + " exactly 10,000 digits is worked out, and a loop over a huge number starts at once");
    }
}
