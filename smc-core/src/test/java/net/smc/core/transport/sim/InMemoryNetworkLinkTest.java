package net.smc.core.transport.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.TreeSet;

import org.junit.jupiter.api.Test;

/** Latency, jitter, loss, duplication and re-ordering of the in-memory network's links. */
class InMemoryNetworkLinkTest {
    private final SimFixture sim = new SimFixture(42);

    @Test
    void datagram_arrivesAfterTheLinkLatency() {
        sim.network.setDefaultLink(LinkProfile.fixed(25));
        SimFixture.Node a = sim.node(1);
        SimFixture.Node b = sim.node(2);
        sim.scheduler.runUntil(100);

        a.send(b, "x");
        sim.scheduler.runUntil(124);
        assertTrue(b.received.isEmpty());
        sim.scheduler.runUntil(125);

        assertEquals(List.of("125 1 x"), b.received);
    }

    @Test
    void zeroLatency_stillDeliversAfterSendReturns() {
        sim.network.setDefaultLink(LinkProfile.fixed(0));
        SimFixture.Node a = sim.node(1);
        SimFixture.Node b = sim.node(2);

        a.send(b, "x");
        assertTrue(b.received.isEmpty());
        sim.runUntilIdle();

        assertEquals(List.of("0 1 x"), b.received);
    }

    @Test
    void aLinksOwnProfile_appliesInItsDirectionOnly() {
        SimFixture.Node a = sim.node(1);
        SimFixture.Node b = sim.node(2);
        sim.network.setLink(a.address(), b.address(), LinkProfile.fixed(40));

        a.send(b, "slow way");
        b.send(a, "default way");
        sim.runUntilIdle();

        assertEquals(List.of("40 1 slow way"), b.received);
        assertEquals(List.of("1 2 default way"), a.received);

        sim.network.clearLinks();
        a.send(b, "default again");
        sim.runUntilIdle();
        assertEquals("41 1 default again", b.received.get(1));
    }

    @Test
    void jitter_spreadsArrivalsOverItsRange_andReordersCloseSends() {
        sim.network.setDefaultLink(LinkProfile.fixed(10).withLatency(10, 20));
        SimFixture.Node a = sim.node(1);
        SimFixture.Node b = sim.node(2);

        for (int i = 0; i < 200; i++) {
            a.send(b, Integer.toString(i));
        }
        sim.runUntilIdle();

        TreeSet<Long> arrivals = new TreeSet<>();
        List<Integer> order = new ArrayList<>();
        for (String line : b.received) {
            String[] parts = line.split(" ");
            arrivals.add(Long.parseLong(parts[0]));
            order.add(Integer.parseInt(parts[2]));
        }
        assertEquals(10, arrivals.first());
        assertEquals(30, arrivals.last());
        assertEquals(21, arrivals.size(), "every jitter value from 0 to 20 ms occurs in 200 draws");
        assertNotEquals(sorted(order), order, "jitter re-orders datagrams sent at the same time");
    }

    @Test
    void withoutJitter_aLinkKeepsItsOrder() {
        SimFixture.Node a = sim.node(1);
        SimFixture.Node b = sim.node(2);

        for (int i = 0; i < 100; i++) {
            a.send(b, Integer.toString(i));
            sim.scheduler.runFor(i % 3);
        }
        sim.runUntilIdle();

        List<Integer> order = b.received.stream().map(line -> Integer.parseInt(line.split(" ")[2])).toList();
        assertEquals(sorted(order), order);
    }

    @Test
    void reorderProbability_holdsSomeDatagramsBack_soLaterOnesOvertakeThem() {
        sim.network.setDefaultLink(LinkProfile.fixed(5).withReorder(0.25, 50));
        SimFixture.Node a = sim.node(1);
        SimFixture.Node b = sim.node(2);

        for (int i = 0; i < 400; i++) {
            a.send(b, Integer.toString(i));
            sim.scheduler.runFor(1);
        }
        sim.runUntilIdle();

        long heldBack = b.received.stream()
                .filter(line -> {
                    String[] p = line.split(" ");
                    return Long.parseLong(p[0]) - Integer.parseInt(p[2]) == 55;
                })
                .count();
        assertEquals(400, b.received.size());
        assertTrue(heldBack > 70 && heldBack < 130, heldBack + " of 400 held back; about 100 expected");
        List<Integer> order = b.received.stream().map(line -> Integer.parseInt(line.split(" ")[2])).toList();
        assertNotEquals(sorted(order), order);
    }

    /** Seed 42, 10,000 datagrams at 30 % loss: the share lost stays within 3 points (about 6 sigma). */
    @Test
    void loss_dropsAboutItsShare_andCountsEachDrop() {
        sim.network.setDefaultLink(LinkProfile.DEFAULT.withLoss(0.3));
        SimFixture.Node a = sim.node(1);
        SimFixture.Node b = sim.node(2);

        for (int i = 0; i < 10_000; i++) {
            a.send(b, "x");
        }
        sim.runUntilIdle();

        NodeCounters atB = b.counters();
        assertEquals(10_000, atB.delivered() + atB.droppedByLoss());
        assertEquals(atB.delivered(), b.received.size());
        double lost = atB.droppedByLoss() / 10_000.0;
        assertTrue(lost > 0.27 && lost < 0.33, "lost share " + lost);
    }

    @Test
    void duplication_deliversSomeDatagramsTwice_andCountsThem() {
        sim.network.setDefaultLink(LinkProfile.DEFAULT.withDuplication(0.2));
        SimFixture.Node a = sim.node(1);
        SimFixture.Node b = sim.node(2);

        for (int i = 0; i < 5_000; i++) {
            a.send(b, Integer.toString(i));
        }
        sim.runUntilIdle();

        NodeCounters atB = b.counters();
        assertEquals(5_000 + atB.duplicated(), atB.delivered());
        assertEquals(5_000 + atB.duplicated(), a.counters().copies());
        assertTrue(atB.duplicated() > 900 && atB.duplicated() < 1_100, atB.duplicated() + " duplicates; about 1000 expected");
        assertEquals(5_000, new TreeSet<>(b.received.stream().map(line -> line.split(" ")[2]).toList()).size());
    }

    @Test
    void receivers_getArraysOfTheirOwn() {
        sim.network.setDefaultLink(LinkProfile.DEFAULT.withDuplication(1.0));
        SimFixture.Node a = sim.node(1);
        List<byte[]> got = new ArrayList<>();
        sim.network.attach(net.smc.core.transport.Address.loopback(2)).setReceiver((from, data) -> {
            got.add(data);
            data[0] = 'Z';
        });

        a.transport.send(net.smc.core.transport.Address.loopback(2), new byte[] {'a'});
        sim.runUntilIdle();

        assertEquals(2, got.size());
        assertTrue(got.get(0) != got.get(1));
    }

    @Test
    void receiversThatChangeTheirArrays_leaveEveryOtherCopyAsSent() {
        sim.network.setDefaultLink(LinkProfile.DEFAULT.withDuplication(0.5));
        SimFixture.Node a = sim.node(1);
        List<String> seen = new ArrayList<>();
        for (int port = 2; port <= 4; port++) {
            int at = port;
            sim.network.attach(net.smc.core.transport.Address.loopback(port)).setReceiver((from, data) -> {
                seen.add(at + ":" + (char) data[0]);
                data[0] = 'Z';
            });
        }
        byte[] sent = {'a'};

        for (int i = 0; i < 20; i++) {
            a.transport.send(net.smc.core.transport.Address.loopback(2), sent);
            a.transport.broadcast(sent);
        }
        sent[0] = 'Z';   // the sender's array is its own again once send returns
        sim.runUntilIdle();

        assertTrue(seen.size() > 80, seen.size() + " copies; some of them duplicates");
        assertTrue(seen.stream().allMatch(s -> s.endsWith(":a")), seen.toString());
    }

    private static List<Integer> sorted(List<Integer> list) {
        return list.stream().sorted().toList();
    }
}
