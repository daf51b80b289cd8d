package net.smc.core.transport.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;

import net.smc.core.transport.Cancellable;

import org.junit.jupiter.api.Test;

class SimulationSchedulerTest {
    private final SimulationScheduler scheduler = new SimulationScheduler();
    private final List<String> log = new ArrayList<>();

    private Runnable note(String what) {
        return () -> log.add(scheduler.nowMillis() + " " + what);
    }

    @Test
    void clock_startsWhereItIsTold() {
        assertEquals(0, new SimulationScheduler().nowMillis());
        assertEquals(1_700_000_000_000L, new SimulationScheduler(1_700_000_000_000L).nowMillis());
    }

    @Test
    void tasks_runInTimeOrder_andTheClockJumpsToEach() {
        scheduler.schedule(30, note("c"));
        scheduler.schedule(10, note("a"));
        scheduler.schedule(20, note("b"));

        assertEquals(3, scheduler.runUntilIdle(10));

        assertEquals(List.of("10 a", "20 b", "30 c"), log);
        assertEquals(30, scheduler.nowMillis());
    }

    @Test
    void tasksDueAtTheSameTime_runInTheOrderTheyWereScheduled() {
        for (int i = 0; i < 100; i++) {
            scheduler.schedule(5, note("t" + i));
        }
        scheduler.runUntilIdle(1_000);

        List<String> expected = new ArrayList<>();
        for (int i = 0; i < 100; i++) {
            expected.add("5 t" + i);
        }
        assertEquals(expected, log);
    }

    @Test
    void zeroDelay_runsAfterTheCurrentTask_andAfterTasksAlreadyDueThen() {
        scheduler.schedule(1, () -> {
            scheduler.schedule(0, note("scheduled by first"));
            log.add("first");
        });
        scheduler.schedule(1, note("second"));

        scheduler.runUntilIdle(10);

        assertEquals(List.of("first", "1 second", "1 scheduled by first"), log);
    }

    @Test
    void runUntil_runsWhatIsDue_thenSetsTheClock() {
        scheduler.schedule(5, note("due"));
        scheduler.schedule(10, note("at the limit"));
        scheduler.schedule(11, note("later"));

        assertEquals(2, scheduler.runUntil(10));

        assertEquals(List.of("5 due", "10 at the limit"), log);
        assertEquals(10, scheduler.nowMillis());
        assertEquals(1, scheduler.pending());
    }

    @Test
    void runUntil_aTimeInThePast_isRefused() {
        scheduler.runUntil(50);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> scheduler.runUntil(49));
        assertEquals("cannot run until 49 ms: the clock is already at 50 ms and never goes back", e.getMessage());
    }

    @Test
    void runFor_advancesByTheDuration() {
        scheduler.runUntil(100);
        scheduler.schedule(30, note("x"));

        scheduler.runFor(20);
        assertEquals(120, scheduler.nowMillis());
        assertTrue(log.isEmpty());

        scheduler.runFor(10);
        assertEquals(List.of("130 x"), log);
    }

    @Test
    void step_runsOneTask_andSaysWhenThereIsNone() {
        scheduler.schedule(1, note("a"));
        scheduler.schedule(2, note("b"));

        assertTrue(scheduler.step());
        assertEquals(List.of("1 a"), log);
        assertTrue(scheduler.step());
        assertFalse(scheduler.step());
        assertEquals(2, scheduler.executed());
    }

    @Test
    void runUntilCondition_stopsAsSoonAsItHolds() {
        for (int i = 1; i <= 10; i++) {
            scheduler.schedule(i, note("t" + i));
        }

        assertTrue(scheduler.runUntil(() -> log.size() == 3, 100));

        assertEquals(3, scheduler.nowMillis());
        assertEquals(7, scheduler.pending());
    }

    @Test
    void runUntilCondition_givesUpAtTheDeadline() {
        scheduler.schedule(5, note("a"));
        scheduler.schedule(50, note("b"));

        assertFalse(scheduler.runUntil(() -> log.size() == 2, 20));

        assertEquals(List.of("5 a"), log);
        assertEquals(1, scheduler.pending());
    }

    @Test
    void cancel_beforeTheTaskIsDue_preventsIt() {
        Cancellable handle = scheduler.schedule(10, note("cancelled"));
        scheduler.schedule(20, note("kept"));

        assertTrue(handle.cancel());
        assertFalse(handle.cancel());
        assertEquals(1, scheduler.pending());
        scheduler.runUntilIdle(10);

        assertEquals(List.of("20 kept"), log);
    }

    @Test
    void cancel_afterTheTaskRan_returnsFalse() {
        Cancellable handle = scheduler.schedule(1, note("ran"));
        scheduler.runUntilIdle(10);
        assertFalse(handle.cancel());
    }

    @Test
    void cancellingMostOfAManyTaskQueue_keepsCountsAndOrderRight() {
        List<Cancellable> handles = new ArrayList<>();
        for (int i = 0; i < 5_000; i++) {
            handles.add(scheduler.schedule(i, note("t" + i)));
        }
        for (int i = 0; i < 5_000; i++) {
            if (i % 10 != 0) {
                handles.get(i).cancel();
            }
        }

        assertEquals(500, scheduler.pending());
        assertEquals(500, scheduler.runUntilIdle(1_000));
        assertEquals("0 t0", log.get(0));
        assertEquals("4990 t4990", log.get(499));
    }

    @Test
    void runUntilIdle_failsWhenTheSimulationNeverGoesIdle() {
        Runnable[] heartbeat = new Runnable[1];
        heartbeat[0] = () -> scheduler.schedule(100, heartbeat[0]);
        scheduler.schedule(0, heartbeat[0]);

        IllegalStateException e = assertThrows(IllegalStateException.class, () -> scheduler.runUntilIdle(50));
        assertEquals("simulation not idle after 50 tasks (limit 50); 1 still pending at 4900 ms", e.getMessage());
    }

    @Test
    void negativeDelay_isRefused() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> scheduler.schedule(-1, note("x")));
        assertEquals("delay of -1 ms is negative; it must be 0 or more", e.getMessage());
    }

    @Test
    void delayBeyondTheEndOfTime_isRefused() {
        SimulationScheduler late = new SimulationScheduler(Long.MAX_VALUE - 10);
        assertThrows(IllegalArgumentException.class, () -> late.schedule(11, () -> { }));
    }

    @Test
    void aTaskThatThrows_stopsTheRunWhereTheFaultIs_andTheNextRunGoesOn() {
        RuntimeException fault = new RuntimeException("boom");
        scheduler.schedule(5, () -> {
            throw fault;
        });
        scheduler.schedule(6, note("after"));

        assertSame(fault, assertThrows(RuntimeException.class, () -> scheduler.runUntilIdle(10)));
        assertEquals(5, scheduler.nowMillis());

        scheduler.runUntilIdle(10);
        assertEquals(List.of("6 after"), log);
    }

    @Test
    void aTaskThatRunsTheScheduler_isRefused() {
        scheduler.schedule(1, scheduler::step);
        scheduler.schedule(2, note("x"));

        IllegalStateException e = assertThrows(IllegalStateException.class, scheduler::step);
        assertEquals("the simulation is already running a task; a task must not run the scheduler", e.getMessage());
    }
}
