package net.smc.core.comm;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;

import net.smc.core.message.MessageType;
import net.smc.core.transport.Address;
import net.smc.core.transport.sim.SimulationScheduler;

class RetryTimerTest {
    private final SimulationScheduler sim = new SimulationScheduler();
    private final List<String> fired = new ArrayList<>();
    private final RetryTimer timer = new RetryTimer(sim, sim, p -> fired.add(sim.nowMillis() + " " + p.id));

    private Pending pending(long id, long deadline) {
        Pending p = new Pending(id, Address.loopback(4001), MessageType.CAPABILITY_REQUEST, List.of(),
                DeliveryListener.IGNORE, 0, 100);
        p.tries = 1;
        p.deadlineMillis = deadline;
        return p;
    }

    @Test
    void timeouts_fireAtTheirDeadlines_inDeadlineThenSendOrder() {
        timer.watch(pending(1, 50));
        timer.watch(pending(2, 20));
        timer.watch(pending(3, 50));
        sim.runUntilIdle(100);
        assertEquals(List.of("20 2", "50 1", "50 3"), fired);
    }

    @Test
    void settledMessages_doNotFire_andUseOneSchedulerTask() {
        Pending a = pending(1, 10);
        Pending b = pending(2, 20);
        timer.watch(a);
        timer.watch(b);
        assertEquals(1, sim.pending(), "one task for all deadlines");
        a.settled = true;
        sim.runUntilIdle(100);
        assertEquals(List.of("20 2"), fired);
        assertEquals(0, timer.size());
    }

    @Test
    void rearmedMessages_fireOnlyForTheirLatestTry() {
        Pending a = pending(1, 10);
        timer.watch(a);
        a.tries = 2;
        a.deadlineMillis = 30;
        timer.watch(a);
        sim.runUntilIdle(100);
        assertEquals(List.of("30 1"), fired);
    }

    @Test
    void stop_cancelsEverything() {
        timer.watch(pending(1, 10));
        timer.stop();
        sim.runUntilIdle(100);
        assertEquals(List.of(), fired);
    }
}
