package net.smc.policy.stdlib;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import net.smc.policy.PolicyEngine;
import net.smc.policy.TimerQueue;
import org.junit.jupiter.api.Test;

/** Timers on a virtual clock: the engine never sleeps; time passes only when the test says so. */
class TimerTest {
    private long now = 1_000;
    private final List<String> lines = new ArrayList<>();

    private PolicyEngine cell(PolicyEngine.Builder builder) {
        return builder.clock(() -> now).output(lines::add).errors(d -> lines.add("error: " + d.message())).build();
    }

    private static final String TICKING = """
            root/event at: "tick" put: (root/factory/event create: #("count")).
            p := root/factory/ecapolicy create.
            p event: root/event/tick; action: [:count | root print: "" + count + "@" + (root load: "DateTime") create secs].
            p active: true.
            root at: "timer" put: (root load: "Timer") create.
            """;

    /** Moves the clock to {@code target}, running each due task at its own due time. */
    private void advanceTo(TimerQueue queue, long target) {
        while (queue.nextDue().isPresent() && queue.nextDue().getAsLong() <= target) {
            now = queue.nextDue().getAsLong();
            queue.runDue();
        }
        now = target;
    }

    @Test
    void repeat_ticksAtEachPeriodOfTheVirtualClock() {
        PolicyEngine cell = cell(PolicyEngine.builder());
        cell.run("t.p2", TICKING + "root/timer repeat: 250 event: root/event/tick.");
        advanceTo(cell.timers(), 1_800);
        assertEquals(List.of("1@1250", "2@1500", "3@1750"), lines);
    }

    @Test
    void nothingRuns_untilTheOwnerRunsTheQueue() {
        PolicyEngine cell = cell(PolicyEngine.builder());
        cell.run("t.p2", TICKING + "root/timer tick: 10 event: root/event/tick.");
        now = 5_000;
        assertEquals(List.of(), lines);
        assertEquals(1, cell.timers().runDue());
        assertEquals(List.of("1@5000"), lines);
    }

    @Test
    void givenScheduler_receivesTheDelays_andCancelCallsTheTaskOff() {
        List<Long> delays = new ArrayList<>();
        List<Runnable> tasks = new ArrayList<>();
        int[] cancelled = {0};
        PolicyEngine cell = cell(PolicyEngine.builder().scheduler((delay, task) -> {
            delays.add(delay);
            tasks.add(task);
            return () -> cancelled[0]++;
        }));
        cell.run("t.p2", TICKING + "i := root/timer repeat: \"1:30\" event: root/event/tick.");
        assertEquals(List.of(90_000L), delays);
        tasks.get(0).run();
        assertEquals(List.of("1@1000"), lines);
        assertEquals(List.of(90_000L, 90_000L), delays);
        cell.run("t.p2", "root/timer cancel: 1");
        assertEquals(1, cancelled[0]);
        assertThrows(IllegalStateException.class, cell::timers);
    }

    @Test
    void stop_thenStart_restartsWithAFullPeriod() {
        PolicyEngine cell = cell(PolicyEngine.builder());
        cell.run("t.p2", TICKING + "root/timer repeat: 100 event: root/event/tick.");
        advanceTo(cell.timers(), 1_150);
        cell.run("t.p2", "root/timer stop: 1");
        advanceTo(cell.timers(), 2_000);
        cell.run("t.p2", "root/timer start: 1");
        advanceTo(cell.timers(), 2_100);
        assertEquals(List.of("1@1100", "2@2100"), lines);
    }

    @Test
    void cancel_leavesNothingPending() {
        PolicyEngine cell = cell(PolicyEngine.builder());
        cell.run("t.p2", TICKING + "root/timer repeat: 100 event: root/event/tick; tick: 50 event: root/event/tick.");
        assertEquals(2, cell.timers().pending());
        cell.run("t.p2", "root/timer cancel");
        assertEquals(0, cell.timers().pending());
    }

    @Test
    void aPolicyError_isReported_andTheTimerGoesOn() {
        PolicyEngine cell = cell(PolicyEngine.builder());
        cell.run("t.p2", TICKING + """
                q := root/factory/ecapolicy create.
                q event: root/event/tick; action: [:count | count / 0].
                q active: true.
                root/timer repeat: 100 event: root/event/tick.
                """);
        advanceTo(cell.timers(), 1_200);
        assertEquals(List.of("1@1100", "error: ObligationPolicy: unhandled action error: division by zero",
                "2@1200", "error: ObligationPolicy: unhandled action error: division by zero"), lines);
        assertEquals(1, cell.timers().pending());
    }

    @Test
    void exitInATick_endsTheCell_andLaterTicksDoNotRun() {
        PolicyEngine cell = cell(PolicyEngine.builder());
        cell.run("t.p2", TICKING + """
                q := root/factory/ecapolicy create.
                q event: root/event/tick; action: [:count | root exit: 4].
                q active: true.
                root/timer repeat: 100 event: root/event/tick.
                """);
        advanceTo(cell.timers(), 1_500);
        assertEquals(List.of("1@1100"), lines);
        assertEquals(4, cell.exitStatus().getAsInt());
    }

    @Test
    void queue_runsTasksInDueOrder_andSameTimeInScheduleOrder() {
        TimerQueue queue = new TimerQueue(() -> now);
        List<String> ran = new ArrayList<>();
        queue.schedule(20, () -> ran.add("b"));
        queue.schedule(10, () -> ran.add("a"));
        queue.schedule(20, () -> ran.add("c"));
        Runnable cancel = queue.schedule(15, () -> ran.add("cancelled"));
        cancel.run();
        cancel.run();
        now += 20;
        assertEquals(3, queue.runDue());
        assertEquals(List.of("a", "b", "c"), ran);
        assertTrue(queue.nextDue().isEmpty());
    }

    @Test
    void queue_refusesANegativeDelay() {
        TimerQueue queue = new TimerQueue(() -> now);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> queue.schedule(-1, () -> { }));
        assertEquals("delay of -1 ms is negative; it must be 0 or more", e.getMessage());
    }
}
