package net.smc.core.transport.sim;

import static java.nio.charset.StandardCharsets.UTF_8;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;

import net.smc.core.transport.Address;
import net.smc.core.transport.Transport;

import org.junit.jupiter.api.Test;

/** One seed, one run: the whole delivery trace replays byte for byte, and every copy is accounted for. */
class InMemoryNetworkDeterminismTest {

    /**
     * Eight chatty nodes on faulty links (jitter, loss, duplication, re-ordering), with a partition,
     * a crash and a restart along the way; each node answers some of what it gets, so the traffic
     * depends on what was delivered before.
     */
    private static SimFixture run(long seed) {
        SimFixture sim = new SimFixture(seed);
        sim.network.setDefaultLink(new LinkProfile(3, 7, 0.1, 0.05, 0.05, 20));
        List<Transport> nodes = new ArrayList<>();
        for (int i = 1; i <= 8; i++) {
            nodes.add(attachChatty(sim, Address.loopback(4000 + i)));
        }
        for (int round = 0; round < 100; round++) {
            Transport sender = nodes.get(round % nodes.size());
            if (round % 5 == 0) {
                sender.broadcast(("round " + round).getBytes(UTF_8));
            } else {
                sender.send(Address.loopback(4001 + (round * 3) % 8), ("round " + round).getBytes(UTF_8));
            }
            if (round == 20) {
                sim.network.partition(Set.of(Address.loopback(4001), Address.loopback(4002)),
                        Set.of(Address.loopback(4005), Address.loopback(4006)));
            }
            if (round == 30) {
                sim.network.crash(Address.loopback(4003));
            }
            if (round == 40) {
                sim.network.heal();
                nodes.set(2, attachRestarted(sim, Address.loopback(4003)));
            }
            sim.scheduler.runFor(4);
        }
        sim.runUntilIdle();
        return sim;
    }

    private static Transport attachChatty(SimFixture sim, Address address) {
        return chatty(sim.network.attach(address));
    }

    private static Transport attachRestarted(SimFixture sim, Address address) {
        return chatty(sim.network.restart(address));
    }

    private static Transport chatty(Transport t) {
        t.setReceiver((from, data) -> {
            String text = new String(data, UTF_8);
            if (!text.startsWith("re:") && text.hashCode() % 3 == 0) {
                t.send(from, ("re: " + text).getBytes(UTF_8));
            }
        });
        return t;
    }

    @Test
    void sameSeed_givesTheSameTraceToTheByte() {
        List<String> first = run(2024).trace;
        List<String> second = run(2024).trace;

        assertTrue(first.size() > 250, "a busy run: " + first.size() + " events");
        assertEquals(String.join("\n", first), String.join("\n", second));
    }

    @Test
    void anotherSeed_givesAnotherTrace() {
        assertNotEquals(run(2024).trace, run(2025).trace);
    }

    @Test
    void theFaultyRun_exercisesEveryKindOfDrop() {
        NodeCounters totals = run(2024).network.totals();

        assertTrue(totals.droppedByLoss() > 0, totals.toString());
        assertTrue(totals.droppedByPartition() > 0, totals.toString());
        assertTrue(totals.droppedWhileDown() > 0, totals.toString());
        assertTrue(totals.duplicated() > 0, totals.toString());
    }

    @Test
    void everyCopy_isEitherDeliveredOrCountedAsDropped() {
        SimFixture sim = run(99);
        NodeCounters totals = sim.network.totals();

        assertEquals(totals.copies(), totals.delivered() + totals.dropped());
        assertEquals(sim.trace.size(), totals.copies());
    }
}
