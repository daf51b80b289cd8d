package net.smc.core.transport.sim;

import static java.nio.charset.StandardCharsets.UTF_8;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;

import net.smc.core.transport.Address;
import net.smc.core.transport.Transport;

import org.junit.jupiter.api.Test;

/** Who can reach whom: broadcast fan-out, partitions, crashes and restarts, the radio hook. */
class InMemoryNetworkTopologyTest {
    private final SimFixture sim = new SimFixture(7);

    @Test
    void broadcast_reachesOtherNodesInAscendingAddressOrder() {
        sim.network.setDefaultLink(LinkProfile.fixed(0));
        SimFixture.Node c = sim.node(30);
        SimFixture.Node a = sim.node(10);
        SimFixture.Node b = sim.node(20);

        b.broadcast("hello");
        sim.runUntilIdle();

        assertEquals(List.of("0 deliver 127.0.0.1:20 -> 127.0.0.1:10 hello",
                "0 deliver 127.0.0.1:20 -> 127.0.0.1:30 hello"), sim.trace);
        assertEquals(1, b.counters().sent());
        assertEquals(2, b.counters().copies());
        assertTrue(b.received.isEmpty());
        assertEquals(1, a.received.size());
        assertEquals(1, c.received.size());
    }

    @Test
    void sentObserver_seesEachDatagramOfALiveSenderOnce_aBroadcastWithNoDestination() {
        sim.network.setDefaultLink(LinkProfile.fixed(0));
        SimFixture.Node a = sim.node(1);
        SimFixture.Node b = sim.node(2);
        SimFixture.Node c = sim.node(3);
        List<String> sent = new ArrayList<>();
        sim.network.addObserver(new NetworkObserver() {
            @Override
            public void sent(long atMillis, Address from, Address to, byte[] data) {
                sent.add(atMillis + " " + from.port() + " -> " + (to == null ? "all" : to.port()) + " " + new String(data, UTF_8));
            }
        });

        a.send(b, "one");
        b.broadcast("two");
        sim.network.partition(Set.of(a.address()), Set.of(c.address()));
        a.send(c, "cut");   // sent, then dropped by the partition
        sim.network.crash(c.address());
        c.send(a, "from the dead");
        sim.runUntilIdle();

        assertEquals(List.of("0 1 -> 2 one", "0 2 -> all two", "0 1 -> 3 cut"), sent);
        assertEquals(List.of("0 drop PARTITION 127.0.0.1:1 -> 127.0.0.1:3 cut",
                "0 drop SENDER_DOWN 127.0.0.1:3 -> 127.0.0.1:1 from the dead",
                "0 deliver 127.0.0.1:1 -> 127.0.0.1:2 one",
                "0 deliver 127.0.0.1:2 -> 127.0.0.1:1 two",
                "0 drop RECEIVER_DOWN 127.0.0.1:2 -> 127.0.0.1:3 two"), sim.trace);
    }

    @Test
    void partition_cutsBothWaysBetweenItsSides_andHealRestoresThem() {
        SimFixture.Node a = sim.node(1);
        SimFixture.Node b = sim.node(2);
        SimFixture.Node c = sim.node(3);
        sim.network.partition(Set.of(a.address()), Set.of(b.address(), c.address()));

        a.send(b, "a to b");
        b.send(a, "b to a");
        b.send(c, "b to c");
        a.broadcast("a to all");
        sim.runUntilIdle();

        assertTrue(a.received.isEmpty());
        assertEquals(List.of("1 2 b to c"), c.received);
        assertEquals(2, b.counters().droppedByPartition());
        assertEquals(1, a.counters().droppedByPartition());
        assertEquals(1, c.counters().droppedByPartition());

        sim.network.heal();
        a.send(b, "healed");
        sim.runUntilIdle();
        assertEquals(List.of("2 1 healed"), b.received);
    }

    @Test
    void partitions_addUp() {
        SimFixture.Node a = sim.node(1);
        SimFixture.Node b = sim.node(2);
        SimFixture.Node c = sim.node(3);
        sim.network.partition(Set.of(a.address()), Set.of(b.address()));
        sim.network.partition(Set.of(a.address()), Set.of(c.address()));

        a.broadcast("x");
        b.send(c, "y");
        sim.runUntilIdle();

        assertTrue(b.received.isEmpty());
        assertEquals(List.of("1 2 y"), c.received);
    }

    @Test
    void partition_withOverlappingSides_isRefused() {
        Address a = Address.loopback(1);
        Address b = Address.loopback(2);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> sim.network.partition(Set.of(a, b), Set.of(b)));
        assertEquals("partition sides overlap at 127.0.0.1:2; a node may be on one side only", e.getMessage());
    }

    @Test
    void partition_withAnEmptySide_isRefused() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> sim.network.partition(Set.of(Address.loopback(1)), Set.of()));
        assertEquals("partition [127.0.0.1:1] | [] has an empty side; each side needs a node", e.getMessage());
    }

    @Test
    void crashedNode_neitherSendsNorReceives_andIsLeftOutOfBroadcasts() {
        SimFixture.Node a = sim.node(1);
        SimFixture.Node b = sim.node(2);
        SimFixture.Node c = sim.node(3);

        sim.network.crash(b.address());
        a.send(b, "to the dead");
        a.broadcast("to all");
        b.send(c, "from the dead");   // the crashed cell does not know: no exception
        b.broadcast("from the dead, to all");
        sim.runUntilIdle();

        assertTrue(b.received.isEmpty());
        assertEquals(List.of("1 1 to all"), c.received);
        assertEquals(4, b.counters().droppedWhileDown(), "one unicast to it; from it, one unicast and a broadcast copy for each of a and c");
        assertEquals(Set.of(a.address(), c.address()), sim.network.attached());
    }

    @Test
    void datagramInFlight_toANodeThatCrashes_isDropped() {
        sim.network.setDefaultLink(LinkProfile.fixed(10));
        SimFixture.Node a = sim.node(1);
        SimFixture.Node b = sim.node(2);

        a.send(b, "in flight");
        sim.scheduler.runFor(5);
        sim.network.crash(b.address());
        sim.runUntilIdle();

        assertTrue(b.received.isEmpty());
        assertEquals(List.of("10 drop RECEIVER_DOWN 127.0.0.1:1 -> 127.0.0.1:2 in flight"), sim.trace);
    }

    @Test
    void datagramInFlight_fromANodeThatCrashes_stillArrives() {
        sim.network.setDefaultLink(LinkProfile.fixed(10));
        SimFixture.Node a = sim.node(1);
        SimFixture.Node b = sim.node(2);

        b.send(a, "last words");
        sim.scheduler.runFor(5);
        sim.network.crash(b.address());
        sim.runUntilIdle();

        assertEquals(List.of("10 2 last words"), a.received);
    }

    @Test
    void restart_givesANewEndpointAtTheSameAddress_andTheOldOneStaysDead() {
        SimFixture.Node a = sim.node(1);
        SimFixture.Node b = sim.node(2);
        sim.network.crash(b.address());

        SimFixture.Node reborn = sim.new Node(sim.network.restart(b.address()));
        a.send(b, "welcome back");
        b.send(a, "old self");
        reborn.send(a, "new self");
        sim.runUntilIdle();

        assertEquals(b.address(), reborn.address());
        assertEquals(List.of("1 1 welcome back"), reborn.received);
        assertTrue(b.received.isEmpty());
        assertEquals(List.of("1 2 new self"), a.received);
    }

    @Test
    void crash_ofAnAddressWithNoNode_isRefused() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> sim.network.crash(Address.loopback(9)));
        assertEquals("no node is attached at 127.0.0.1:9; only an attached node can crash", e.getMessage());
    }

    @Test
    void restart_ofANodeThatDidNotCrash_isRefused() {
        SimFixture.Node a = sim.node(1);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> sim.network.restart(a.address()));
        assertEquals("node 127.0.0.1:1 has not crashed; only a crashed node can restart", e.getMessage());
    }

    @Test
    void attach_toATakenAddress_isRefused_untilItsNodeCloses() {
        Transport first = sim.network.attach(Address.loopback(1));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> sim.network.attach(Address.loopback(1)));
        assertEquals("address 127.0.0.1:1 is already attached; close or crash its node first", e.getMessage());

        first.close();
        sim.network.attach(Address.loopback(1));
    }

    @Test
    void closingAnOldEndpoint_doesNotDetachItsSuccessor() {
        SimFixture.Node a = sim.node(1);
        SimFixture.Node b = sim.node(2);
        sim.network.crash(b.address());
        SimFixture.Node reborn = sim.new Node(sim.network.restart(b.address()));

        b.transport.close();
        a.send(reborn, "still here?");
        sim.runUntilIdle();

        assertEquals(List.of("1 1 still here?"), reborn.received);
    }

    @Test
    void radioModel_decidesWhoHearsWhom_perCopy() {
        SimFixture.Node a = sim.node(1);
        SimFixture.Node b = sim.node(2);
        SimFixture.Node c = sim.node(3);
        sim.network.setRadio((from, to) -> Math.abs(from.port() - to.port()) <= 1);   // a line of robots

        a.broadcast("from one end");
        c.send(a, "too far");
        sim.runUntilIdle();

        assertEquals(List.of("1 1 from one end"), b.received);
        assertTrue(c.received.isEmpty());
        assertTrue(a.received.isEmpty());
        assertEquals(1, c.counters().droppedByRadio());
        assertEquals(1, a.counters().droppedByRadio());
    }

    @Test
    void datagram_beforeTheReceiverIsSet_isDroppedAndCounted() {
        SimFixture.Node a = sim.node(1);
        Transport bare = sim.network.attach(Address.loopback(2));

        a.transport.send(bare.localAddress(), "early".getBytes(UTF_8));
        sim.runUntilIdle();

        assertEquals(1, sim.network.counters(bare.localAddress()).droppedNoReceiver());
    }

    @Test
    void datagram_toAnAddressNobodyHolds_isCountedThere() {
        SimFixture.Node a = sim.node(1);

        a.transport.send(Address.loopback(99), "anyone?".getBytes(UTF_8));
        sim.runUntilIdle();

        assertEquals(1, sim.network.counters(Address.loopback(99)).droppedWhileDown());
    }
}
