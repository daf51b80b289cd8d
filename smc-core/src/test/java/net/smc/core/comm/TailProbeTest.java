package net.smc.core.comm;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Set;

import org.junit.jupiter.api.Test;

import net.smc.core.message.CapabilityRequest;
import net.smc.core.transport.sim.LinkProfile;

/**
 * The last critical message sent to a peer, lost, goes again two smoothed round trips after it left
 * (the tail probe of {@link MessageSender}) instead of at its timeout: on the in-memory network with
 * links of a fixed 5 ms each way (round trips of 10 ms), so a probe waits 20 ms against a first
 * timeout of 30 ms once a round trip is measured, 200 ms before.
 */
class TailProbeTest {
    /** Initial 200 ms, doubling to 1 s, 4 tries, no jitter, floor 5 ms: the first timeout follows round trips. */
    private static final SenderSettings ADAPTIVE = new SenderSettings(200, 2.0, 1_000, 4, 0.0, 60_000, 1_000, 5);

    private final SimNet net = new SimNet(Net.Faults.NONE, 1, ADAPTIVE);
    private final Peer a;
    private final Peer b;

    TailProbeTest() {
        net.network.setDefaultLink(LinkProfile.fixed(5));
        a = net.peer("uav-a");
        b = net.peer("uav-b");
    }

    /** One message from a to b, acknowledged: a round trip of 10 ms measured (first timeout 30 ms). */
    private void measure() {
        int before = a.settled.get();
        a.send(b, new CapabilityRequest("role"));
        net.awaitUntil(() -> a.settled.get() == before + 1, 5_000);
    }

    /** a sends b a message whose first copy is lost; its id. */
    private long lostOnce(String what) {
        net.network.partition(Set.of(a.address()), Set.of(b.address()));
        long id = a.send(b, new CapabilityRequest(what));
        net.network.heal();
        return id;
    }

    @Test
    void theLastMessageLost_goesAgainAfterTwoRoundTrips_notAtItsTimeout() {
        measure();
        MessageSender s = a.manager.sender();
        assertEquals(30, s.firstTimeoutMillis(b.address()));
        long sent = net.scheduler.nowMillis();
        long lost = lostOnce("last");
        net.awaitUntil(() -> a.outcomes.get(lost).result != null, 5_000);
        assertEquals("delivered", a.outcomes.get(lost).result);
        assertEquals(20 + 10, a.outcomes.get(lost).settledMillis - sent, "probed at 20 ms, not at the 30 ms timeout");
        assertEquals(1, s.counters().probes());
    }

    @Test
    void aPeerNotMeasured_isProbedFromItsFirstAck() {
        MessageSender s = a.manager.sender();
        long sent = net.scheduler.nowMillis();
        long first = a.send(b, new CapabilityRequest("first"));
        long lost = lostOnce("second");
        net.awaitUntil(() -> a.outcomes.get(first).result != null && a.outcomes.get(lost).result != null, 5_000);
        assertEquals(10, a.outcomes.get(first).settledMillis - sent);
        // The first's Ack at 10 ms measures the peer: the second, sent at 0, is probed 20 ms after, not at 200.
        assertEquals(10 + 20 + 10, a.outcomes.get(lost).settledMillis - sent);
        assertEquals(1, s.counters().probes());
    }

    @Test
    void aProbeIntoALinkStillDown_leavesTheTimeoutsAsTheyWere() {
        measure();
        MessageSender s = a.manager.sender();
        long sent = net.scheduler.nowMillis();
        net.network.partition(Set.of(a.address()), Set.of(b.address()));
        long lost = a.send(b, new CapabilityRequest("lost"));
        net.scheduler.schedule(35, net.network::heal); // the probe at 20 ms and the first try are lost
        net.awaitUntil(() -> a.outcomes.get(lost).result != null, 5_000);
        // The second try at the 30 ms timeout (lost), the third 60 ms later, as without a probe.
        assertEquals(30 + 60 + 10, a.outcomes.get(lost).settledMillis - sent);
        assertEquals(1, s.counters().probes());
        assertEquals(2, s.counters().retransmitted());
    }

    @Test
    void aMessageAcknowledgedInTime_isNotProbed() {
        measure();
        for (int i = 0; i < 10; i++) {
            a.send(b, new CapabilityRequest("r" + i));
            net.scheduler.runFor(3);
        }
        net.awaitUntil(() -> a.settled.get() == 11, 5_000);
        assertEquals(0, a.manager.sender().counters().probes());
        assertEquals(0, a.manager.sender().counters().retransmitted());
        assertEquals(0, b.manager.sender().counters().duplicates());
    }

    @Test
    void withAFixedTimeout_noMessageIsProbed() {
        SimNet fixedNet = new SimNet(Net.Faults.NONE, 1, new SenderSettings(30, 2.0, 1_000, 4, 0.0, 60_000, 1_000));
        fixedNet.network.setDefaultLink(LinkProfile.fixed(5));
        Peer x = fixedNet.peer("uav-x");
        Peer y = fixedNet.peer("uav-y");
        long sent = fixedNet.scheduler.nowMillis();
        fixedNet.network.partition(Set.of(x.address()), Set.of(y.address()));
        long lost = x.send(y, new CapabilityRequest("lost"));
        fixedNet.network.heal();
        fixedNet.awaitUntil(() -> x.outcomes.get(lost).result != null, 5_000);
        assertEquals(30 + 10, x.outcomes.get(lost).settledMillis - sent);
        assertEquals(0, x.manager.sender().counters().probes());
    }
}
