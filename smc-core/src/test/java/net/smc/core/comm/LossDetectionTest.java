package net.smc.core.comm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Set;

import org.junit.jupiter.api.Test;

import net.smc.core.message.CapabilityRequest;
import net.smc.core.transport.sim.LinkProfile;

/**
 * A critical message lost before its timeout, found by the Ack of one sent after it to the same peer
 * ({@link LossDetector}), on the in-memory network: links of a fixed 5 ms each way (round trips of
 * 10 ms), so the reordering window is a quarter of that, 3 ms, against a first timeout of 30 ms.
 */
class LossDetectionTest {
    /** Initial 200 ms, doubling to 1 s, 4 tries, no jitter, floor 5 ms: the first timeout follows round trips. */
    private static final SenderSettings ADAPTIVE = new SenderSettings(200, 2.0, 1_000, 4, 0.0, 60_000, 1_000, 5);

    private static SimNet net(SenderSettings settings) {
        SimNet net = new SimNet(Net.Faults.NONE, 1, settings);
        net.network.setDefaultLink(LinkProfile.fixed(5));
        return net;
    }

    private SimNet net;
    private Peer a;
    private Peer b;

    /** The network with adaptive timeouts, peers a and b on it, and one round trip from a to b measured. */
    private void measuredPair() {
        net = net(ADAPTIVE);
        a = net.peer("uav-a");
        b = net.peer("uav-b");
        measure(net, a, b);
    }

    /** Sends one message from a to b and waits for its Ack: a round trip measured (estimate 30 ms). */
    private static void measure(SimNet net, Peer a, Peer b) {
        int before = a.settled.get();
        a.send(b, new CapabilityRequest("role"));
        net.awaitUntil(() -> a.settled.get() == before + 1, 5_000);
    }

    /** a sends b two messages; the first one's first copy is lost. Its id, then the second's. */
    private static long[] firstLostThenSecond(SimNet net, Peer a, Peer b) {
        net.network.partition(Set.of(a.address()), Set.of(b.address()));
        long lost = a.send(b, new CapabilityRequest("first"));
        net.network.heal();
        long next = a.send(b, new CapabilityRequest("second"));
        return new long[] {lost, next};
    }

    @Test
    void aMessageLostAheadOfAnother_goesAgainOnceTheOthersAckIsInAndTheWindowHasPassed() {
        measuredPair();
        MessageSender s = a.manager.sender();
        assertEquals(30, s.firstTimeoutMillis(b.address()));
        long sent = net.scheduler.nowMillis();
        long[] ids = firstLostThenSecond(net, a, b);
        long lost = ids[0];
        long next = ids[1];
        net.awaitUntil(() -> a.outcomes.get(lost).result != null && a.outcomes.get(next).result != null, 5_000);
        assertEquals(10, a.outcomes.get(next).settledMillis - sent);
        // The second's Ack at 10 ms; 3 ms later the first goes again, and its Ack comes 10 ms after.
        assertEquals(10 + 3 + 10, a.outcomes.get(lost).settledMillis - sent, "not at the 30 ms timeout");
        assertEquals(1, s.counters().retransmitted());
        assertEquals(1, s.counters().fastRetransmitted());
        assertEquals(0, b.manager.sender().counters().duplicates(), "the first copy was lost: no copy twice");
        // Two samples of 10 ms (rttvar 5, then 3.75): 10 + 4 x 3.75; a timeout would have doubled it.
        assertEquals(25, s.firstTimeoutMillis(b.address()), "a loss found this way doubles no timeout");
        assertEquals(10.0, s.rtt().smoothedRttMillis(b.address()), 1e-9, "Karn's rule: no sample from the retransmitted one");
        assertEquals(0, s.losses().size(), "nothing is left waiting once both are acknowledged");
    }

    @Test
    void messagesAcknowledgedInTheOrderSent_areNeverSentAgain() {
        measuredPair();
        for (int i = 0; i < 20; i++) {
            a.send(b, new CapabilityRequest("r" + i));
        }
        net.awaitUntil(() -> a.settled.get() == 21, 5_000);
        assertEquals(0, a.manager.sender().counters().retransmitted());
        assertEquals(0, a.manager.sender().losses().size());
    }

    @Test
    void aCopyOvertakenWithinTheWindow_isNotSentAgain() {
        measuredPair();
        // The first copy takes 2 ms longer than the second: its Ack comes 2 ms after the second's, within the 3 ms window.
        net.network.setLink(a.address(), b.address(), LinkProfile.fixed(7));
        long slow = a.send(b, new CapabilityRequest("slow"));
        net.network.setLink(a.address(), b.address(), LinkProfile.fixed(5));
        long fast = a.send(b, new CapabilityRequest("fast"));
        net.awaitUntil(() -> a.outcomes.get(slow).result != null && a.outcomes.get(fast).result != null, 5_000);
        assertEquals("delivered", a.outcomes.get(slow).result);
        assertEquals(0, a.manager.sender().counters().retransmitted());
        assertEquals(0, b.manager.sender().counters().duplicates());
    }

    @Test
    void withAFixedTimeout_aLostMessageWaitsForItsTimeout() {
        SenderSettings fixed = new SenderSettings(30, 2.0, 1_000, 4, 0.0, 60_000, 1_000);
        net = net(fixed);
        a = net.peer("uav-a");
        b = net.peer("uav-b");
        assertNull(a.manager.sender().losses());
        long sent = net.scheduler.nowMillis();
        long lost = firstLostThenSecond(net, a, b)[0];
        net.awaitUntil(() -> a.settled.get() == 2, 5_000);
        assertEquals(30 + 10, a.outcomes.get(lost).settledMillis - sent);
        assertEquals(0, a.manager.sender().counters().fastRetransmitted());
    }

    @Test
    void aSuspectIsSentAgainOnce_andThenBacksOffAsAnyRetransmission() {
        measuredPair();
        long sent = net.scheduler.nowMillis();
        // b cannot hear a until 40 ms: the first message's first copy and its fast retransmission are lost.
        long lost = firstLostThenSecond(net, a, b)[0];
        net.scheduler.schedule(11, () -> net.network.partition(Set.of(a.address()), Set.of(b.address())));
        net.scheduler.schedule(40, net.network::heal);
        net.awaitUntil(() -> a.settled.get() == 3, 5_000);
        assertEquals("delivered", a.outcomes.get(lost).result);
        assertEquals(1, a.manager.sender().counters().fastRetransmitted(), "suspected once");
        // Second try at 13 ms (lost), third at 13 + 60 (the 30 ms first timeout doubled), Ack 10 ms later.
        assertEquals(13 + 60 + 10, a.outcomes.get(lost).settledMillis - sent);
    }
}
