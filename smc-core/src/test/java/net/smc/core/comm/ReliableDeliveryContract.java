package net.smc.core.comm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

import net.smc.core.message.CapabilityRequest;
import net.smc.core.message.Heartbeat;
import net.smc.core.message.RoleEvent;

/**
 * Reliable delivery, one suite for every transport (the in-memory network and Netty UDP): each
 * critical message is delivered to the receiving application exactly once or reported failed, and
 * reported failed within the settings' bound when the peer is unreachable.
 */
abstract class ReliableDeliveryContract {
    /** Short timeouts so that a run with faults ends soon: gives up after at most 1,008 ms. */
    static final SenderSettings SETTINGS = SenderSettings.DEFAULTS.withRetransmission(20, 2.0, 100, 10);
    static final Net.Faults HARSH = new Net.Faults(0.30, 0.10, 0.10);

    private final List<Net> nets = new ArrayList<>();

    /** A network whose links have {@code faults}, with seed {@code seed} where it matters. */
    protected abstract Net newNet(Net.Faults faults, long seed);

    Net net(Net.Faults faults, long seed) {
        Net n = newNet(faults, seed);
        nets.add(n);
        return n;
    }

    @AfterEach
    void closeNets() {
        nets.forEach(Net::close);
    }

    @Test
    void send_deliversEachCriticalMessageOnceAndReportsDelivered_onACleanNetwork() {
        Net net = net(Net.Faults.NONE, 1);
        Peer a = net.peer("uav-a");
        Peer b = net.peer("uav-b");
        List<Long> ids = sendMany(net, a, b, 50);
        net.awaitUntil(() -> a.settled.get() == 50, 10_000);
        for (long id : ids) {
            assertEquals("delivered", a.outcomes.get(id).result, "outcome of message " + id);
            assertEquals(1, b.times(a, id), "deliveries of message " + id);
        }
        assertEquals(50, a.manager.sender().counters().acked());
        assertEquals(0, a.manager.sender().outstanding());
    }

    @Test
    void send_deliversOnceOrReportsFailed_underLossDuplicationAndReordering() {
        Net net = net(HARSH, 7);
        Peer a = net.peer("uav-a");
        Peer b = net.peer("uav-b");
        List<Long> ids = sendMany(net, a, b, 50);
        net.awaitUntil(() -> a.settled.get() == 50, 10_000);
        checkOnceOrFailed(a, b, ids);
        SenderCounters c = a.manager.sender().counters();
        assertTrue(c.retransmitted() > 0, "30% loss must cause retransmissions: " + c);
        assertTrue(c.acked() >= 45, "most messages should get through 10 tries at 30% loss: " + c);
    }

    @Test
    void send_isReliableBothWays_whenTwoCellsSendToEachOtherAtOnce() {
        Net net = net(HARSH, 11);
        Peer a = net.peer("uav-a");
        Peer b = net.peer("uav-b");
        List<Long> fromA = sendMany(net, a, b, 30);
        List<Long> fromB = sendMany(net, b, a, 30);
        net.awaitUntil(() -> a.settled.get() == 30 && b.settled.get() == 30, 10_000);
        checkOnceOrFailed(a, b, fromA);
        checkOnceOrFailed(b, a, fromB);
    }

    @Test
    void send_reportsEveryMessageFailedWithinTheBound_whenThePeerIsUnreachable() {
        Net net = net(Net.Faults.NONE, 3);
        Peer a = net.peer("uav-a");
        Peer b = net.peer("uav-b");
        net.makeUnreachable(b);
        List<Long> ids = sendMany(net, a, b, 20);
        long bound = SETTINGS.failureBoundMillis();
        net.awaitUntil(() -> a.settled.get() == 20, bound + net.slackMillis() + 5_000);
        for (long id : ids) {
            Peer.Outcome o = a.outcomes.get(id);
            assertEquals(FailureReason.NO_ACK.name(), o.result, "outcome of message " + id);
            assertTrue(o.settledMillis - o.sentMillis <= bound + net.slackMillis(), "message " + id + " failed after "
                    + (o.settledMillis - o.sentMillis) + " ms; the bound is " + bound + " ms");
        }
        assertEquals(20 * 9, a.manager.sender().counters().retransmitted());
    }

    @Test
    void send_fragmentsAndReassemblesALargeCriticalMessage() {
        Net net = net(Net.Faults.NONE, 5);
        Peer a = net.peer("uav-a");
        Peer b = net.peer("uav-b");
        long[] id = new long[1];
        // A role event's strings go as they are (a policy text this long would be deflated into one datagram).
        net.onCell(a, () -> id[0] = a.send(b, new RoleEvent("relay", "bulk", List.of("x".repeat(4_000), "y".repeat(1_000)))));
        net.awaitUntil(() -> a.settled.get() == 1, 10_000);
        assertEquals("delivered", a.outcomes.get(id[0]).result);
        assertEquals(1, b.times(a, id[0]));
        assertTrue(b.manager.counters().fragmentsHeld() >= 3, b.manager.counters().toString());
    }

    @Test
    void send_connectionlessMessageReachesTheRouterWithoutAnAck() {
        Net net = net(Net.Faults.NONE, 9);
        Peer a = net.peer("uav-a");
        Peer b = net.peer("uav-b");
        net.onCell(a, () -> a.manager.send(b.address(), new Heartbeat("leader", 1, 0)));
        net.awaitUntil(() -> b.receivedTotal.get() == 1, 10_000);
        assertEquals(0, b.manager.sender().counters().acksSent());
        assertEquals(1, a.manager.counters().unicasts());
    }

    /** Sends {@code n} critical messages from {@code a} to {@code b}, all at once (pipelined). */
    static List<Long> sendMany(Net net, Peer a, Peer b, int n) {
        List<Long> ids = new ArrayList<>();
        net.onCell(a, () -> {
            for (int i = 0; i < n; i++) {
                ids.add(a.send(b, new CapabilityRequest("role-" + i)));
            }
        });
        return ids;
    }

    /** Each message reported exactly once; delivered ones reached the application once, failed ones at most once. */
    static void checkOnceOrFailed(Peer a, Peer b, List<Long> ids) {
        for (long id : ids) {
            Peer.Outcome o = a.outcomes.get(id);
            assertEquals(1, o.calls.get(), "outcome calls for message " + id);
            int times = b.times(a, id);
            if ("delivered".equals(o.result)) {
                assertEquals(1, times, "deliveries of acknowledged message " + id);
            } else {
                assertEquals(FailureReason.NO_ACK.name(), o.result, "outcome of message " + id);
                assertTrue(times <= 1, "message " + id + " reached the application " + times + " times");
            }
        }
        for (String key : b.received.keySet()) {
            if (key.startsWith(a.id() + "#")) {
                long id = Long.parseLong(key.substring(key.indexOf('#') + 1));
                assertTrue(ids.contains(id), "message " + key + " was never sent");
            }
        }
    }
}
