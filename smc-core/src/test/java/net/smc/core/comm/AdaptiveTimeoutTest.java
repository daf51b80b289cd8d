package net.smc.core.comm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Set;

import org.junit.jupiter.api.Test;

import net.smc.core.message.CapabilityRequest;
import net.smc.core.message.RoleEvent;
import net.smc.core.transport.sim.CpuModel;
import net.smc.core.transport.sim.LinkProfile;

/**
 * The Message-Sender's adaptive first timeout on the in-memory network (virtual time, links of a
 * fixed 5 ms each way, so every round trip is 10 ms): samples from Acks and from replies measured
 * outside the sender, Karn's rule, the cell's estimate for a peer never measured, timers that run
 * from when a message has left the transport's queue, and the fixed schedule's give-up time.
 */
class AdaptiveTimeoutTest {
    /** Initial 200 ms, doubling to 1 s, 4 tries, no jitter, floor 5 ms. */
    private static final SenderSettings ADAPTIVE = new SenderSettings(200, 2.0, 1_000, 4, 0.0, 60_000, 1_000, 5);

    private SimNet net(SenderSettings settings) {
        SimNet net = new SimNet(Net.Faults.NONE, 1, settings);
        net.network.setDefaultLink(LinkProfile.fixed(5));
        return net;
    }

    private static long deliverOne(SimNet net, Peer a, Peer b) {
        int before = a.settled.get();
        long sent = net.scheduler.nowMillis();
        long id = a.send(b, new CapabilityRequest("role"));
        net.awaitUntil(() -> a.settled.get() == before + 1, 5_000);
        assertEquals("delivered", a.outcomes.get(id).result);
        return a.outcomes.get(id).settledMillis - sent;
    }

    @Test
    void ackOfAMessageSentOnce_isARoundTripSample() {
        SimNet net = net(ADAPTIVE);
        Peer a = net.peer("uav-a");
        Peer b = net.peer("uav-b");
        MessageSender s = a.manager.sender();
        assertEquals(200, s.firstTimeoutMillis(b.address()), "nothing measured: the initial timeout");
        deliverOne(net, a, b);
        assertEquals(10.0, s.rtt().smoothedRttMillis(b.address()), 1e-9);
        assertEquals(10 + 4 * 5, s.firstTimeoutMillis(b.address()));
    }

    @Test
    void lostFirstCopy_isRetransmittedAfterTheEstimate_andItsAckIsNoSample() {
        SimNet net = net(ADAPTIVE);
        Peer a = net.peer("uav-a");
        Peer b = net.peer("uav-b");
        MessageSender s = a.manager.sender();
        deliverOne(net, a, b); // estimate 30 ms
        net.network.partition(Set.of(a.address()), Set.of(b.address()));
        net.scheduler.schedule(25, net.network::heal); // the tail probe at 20 ms is lost too
        assertEquals(30 + 10, deliverOne(net, a, b), "retransmitted at the 30 ms estimate, not the 200 ms initial timeout");
        assertEquals(1, s.counters().probes());
        assertEquals(1, s.counters().retransmitted());
        assertEquals(10.0, s.rtt().smoothedRttMillis(b.address()), 1e-9,
                "Karn's rule: the 40 ms from the first copy to the Ack of the second is no sample");
        assertEquals(60, s.firstTimeoutMillis(b.address()), "the first try's timeout doubled the estimate");
    }

    @Test
    void roundTripMeasuredOutsideTheSender_timesTheFirstMessageToThatPeer() {
        SimNet net = net(ADAPTIVE);
        Peer a = net.peer("uav-a");
        Peer b = net.peer("uav-b");
        MessageSender s = a.manager.sender();
        s.roundTrip(b.address(), 10); // as a discovery reply gives it, before anything critical went to b
        assertEquals(30, s.firstTimeoutMillis(b.address()));
        net.network.partition(Set.of(a.address()), Set.of(b.address()));
        net.scheduler.schedule(25, net.network::heal); // the tail probe at 20 ms is lost too
        assertEquals(30 + 10, deliverOne(net, a, b), "a first contact whose first copy is lost: repaired after 30 ms");
    }

    @Test
    void peerNeverMeasured_getsTheCellsEstimate() {
        SimNet net = net(ADAPTIVE);
        Peer a = net.peer("uav-a");
        Peer b = net.peer("uav-b");
        Peer c = net.peer("uav-c");
        MessageSender s = a.manager.sender();
        deliverOne(net, a, b);
        assertEquals(30, s.cellTimeoutMillis());
        net.network.partition(Set.of(a.address()), Set.of(c.address()));
        net.scheduler.schedule(15, net.network::heal);
        assertEquals(30 + 10, deliverOne(net, a, c), "c was never measured: b's round trips time it");
    }

    /** Peers a, b, c on a 10 kB/s radio (a 1.3 kB datagram occupies it 130 ms), each measured at 10 ms. */
    private static Peer[] slowRadio(SimNet net) {
        net.network.setCpuModel(CpuModel.FREE);
        net.network.setBandwidth(10_000);
        Peer[] p = {net.peer("uav-a"), net.peer("uav-b"), net.peer("uav-c")};
        p[0].manager.sender().roundTrip(p[1].address(), 10);
        p[0].manager.sender().roundTrip(p[2].address(), 10);
        return p;
    }

    @Test
    void timerRunsFromWhenTheMessageLeftTheQueue_soAQueuedMessageIsNotRetransmitted() {
        SimNet net = net(ADAPTIVE);
        Peer[] p = slowRadio(net);
        MessageSender s = p[0].manager.sender();
        // A role event of long strings: a policy text this long would go deflated, far shorter.
        p[0].send(p[1], new RoleEvent("relay", "bulk", List.of("x".repeat(1_180)))); // one datagram, about 130 ms of radio
        long sent = net.scheduler.nowMillis();
        long id = p[0].send(p[2], new CapabilityRequest("role"));
        net.awaitUntil(() -> p[0].settled.get() == 2, 5_000);
        assertEquals("delivered", p[0].outcomes.get(id).result);
        assertTrue(p[0].outcomes.get(id).settledMillis - sent > 130, "the request waited behind the file");
        assertEquals(0, s.counters().retransmitted(), "nothing went again while it waited in the queue: " + s.counters());
        assertEquals(0, p[2].manager.sender().counters().duplicates());
        assertTrue(s.rtt().smoothedRttMillis(p[2].address()) < 20,
                "the round trip is measured from when the request left: " + s.rtt().smoothedRttMillis(p[2].address()));
    }

    @Test
    void behindADeepQueue_noTryWaitsLongerThanTheFixedTimeout() {
        SimNet net = net(ADAPTIVE);
        Peer[] p = slowRadio(net);
        p[0].send(p[1], new RoleEvent("relay", "bulk", List.of("x".repeat(2_980)))); // three datagrams, about 320 ms of radio
        long id = p[0].send(p[2], new CapabilityRequest("role"));
        net.scheduler.runUntil(() -> false, net.scheduler.nowMillis() + 201);
        assertEquals(2, p[0].manager.sender().counters().retransmitted(),
                "the file and the request went again at the fixed 200 ms from the send, the request's first copy still queued");
        net.awaitUntil(() -> p[0].settled.get() == 2, 5_000);
        assertEquals("delivered", p[0].outcomes.get(id).result);
        net.scheduler.runUntil(() -> false, net.scheduler.nowMillis() + 2_000);
        assertEquals(1, p[2].manager.sender().counters().duplicates(), "both copies of the request arrived");
    }

    @Test
    void unreachablePeer_isGivenUpOnAtTheFixedSchedulesTime_afterMaxTries() {
        SenderSettings jittered = ADAPTIVE.withJitter(0.2);
        for (long seed = 1; seed <= 5; seed++) {
            SimNet net = new SimNet(Net.Faults.NONE, seed, jittered);
            net.network.setDefaultLink(LinkProfile.fixed(5));
            Peer a = net.peer("uav-a");
            Peer b = net.peer("uav-b");
            a.manager.sender().roundTrip(b.address(), 10);
            net.makeUnreachable(b);
            long sent = net.scheduler.nowMillis();
            long id = a.send(b, new CapabilityRequest("role"));
            net.awaitUntil(() -> a.settled.get() == 1, jittered.failureBoundMillis() + 1);
            long after = a.outcomes.get(id).settledMillis - sent;
            assertEquals(FailureReason.NO_ACK.name(), a.outcomes.get(id).result);
            // fixed schedule: 200 + 400 + 800 + 1000 = 2400 ms, +-20 %: given up between 1920 and 2880 ms
            assertEquals(2_400, jittered.fixedScheduleMillis());
            assertTrue(after >= 1_920 && after <= jittered.failureBoundMillis(), "gave up after " + after + " ms");
            assertEquals(jittered.maxTries() - 1, a.manager.sender().counters().retransmitted(),
                    "as many tries as the fixed schedule, only sooner");
        }
    }

    @Test
    void fixedSettings_keepTheInitialTimeout_andMeasureNothing() {
        SimNet net = net(new SenderSettings(200, 2.0, 1_000, 4, 0.0, 60_000, 1_000));
        Peer a = net.peer("uav-a");
        Peer b = net.peer("uav-b");
        a.manager.sender().roundTrip(b.address(), 10);
        deliverOne(net, a, b);
        assertEquals(200, a.manager.sender().firstTimeoutMillis(b.address()));
        assertEquals(200, a.manager.sender().cellTimeoutMillis());
    }
}
