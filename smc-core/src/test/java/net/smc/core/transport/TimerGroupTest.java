package net.smc.core.transport;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;

import net.smc.core.transport.sim.SimulationScheduler;

import org.junit.jupiter.api.Test;

class TimerGroupTest {
    private final SimulationScheduler scheduler = new SimulationScheduler();
    private final List<String> ran = new ArrayList<>();

    @Test
    void cancelAll_stopsThePendingTasksOfTheGroupOnly() {
        TimerGroup crashed = new TimerGroup(scheduler);
        TimerGroup alive = new TimerGroup(scheduler);
        crashed.schedule(10, () -> ran.add("crashed heartbeat"));
        alive.schedule(10, () -> ran.add("alive heartbeat"));

        assertEquals(1, crashed.cancelAll());
        scheduler.runUntilIdle(100);

        assertEquals(List.of("alive heartbeat"), ran);
    }

    @Test
    void tasksThatRan_areForgotten() {
        TimerGroup group = new TimerGroup(scheduler);
        group.schedule(1, () -> ran.add("early"));
        group.schedule(5, () -> ran.add("late"));

        scheduler.runUntil(2);

        assertEquals(1, group.pending());
        assertEquals(1, group.cancelAll());
        assertEquals(0, group.pending());
        scheduler.runUntilIdle(100);
        assertEquals(List.of("early"), ran);
    }

    @Test
    void cancel_ofOneTask_removesItFromTheGroup() {
        TimerGroup group = new TimerGroup(scheduler);
        Cancellable handle = group.schedule(1, () -> ran.add("x"));

        assertTrue(handle.cancel());
        assertFalse(handle.cancel());
        assertEquals(0, group.pending());
        assertEquals(0, group.cancelAll());
    }
}
