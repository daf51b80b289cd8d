package net.smc.core.comm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Set;

import org.junit.jupiter.api.Test;

import net.smc.core.transport.sim.LinkProfile;

/** The reliable-delivery suite on the in-memory network, plus what only simulation can show: many seeds, replay, partitions. */
class SimReliableDeliveryTest extends ReliableDeliveryContract {

    @Override
    protected Net newNet(Net.Faults faults, long seed) {
        return new SimNet(faults, seed, SETTINGS);
    }

    @Test
    void send_deliversOnceOrReportsFailed_forTwoHundredSeedsOfFiftyMessages() {
        long acked = 0;
        long ackIds = 0;
        long ackDatagrams = 0;
        for (long seed = 1; seed <= 200; seed++) {
            SimNet net = new SimNet(HARSH, seed, SETTINGS);
            Peer a = net.peer("uav-a");
            Peer b = net.peer("uav-b");
            List<Long> ids = sendMany(net, a, b, 50);
            net.awaitUntil(() -> a.settled.get() == 50, 60_000);
            checkOnceOrFailed(a, b, ids);
            for (long id : ids) {
                Peer.Outcome o = a.outcomes.get(id);
                assertTrue(o.settledMillis - o.sentMillis <= SETTINGS.failureBoundMillis(),
                        "seed " + seed + ": message " + id + " settled after " + (o.settledMillis - o.sentMillis) + " ms");
            }
            acked += a.manager.sender().counters().acked();
            ackIds += b.manager.sender().counters().acksSent();
            ackDatagrams += b.manager.sender().counters().ackDatagrams();
        }
        // Acknowledgements were coalesced: exactly-once held with Acks carrying several ids.
        assertTrue(ackDatagrams < ackIds, ackDatagrams + " ack datagrams for " + ackIds + " acknowledged copies");
        // 10 tries of a round trip that survives with probability 0.49: about 1 in 800 messages fails.
        assertTrue(acked >= 200 * 50 * 99 / 100, "acked " + acked + " of 10,000");
    }

    @Test
    void run_isDeterministicPerSeed() {
        assertEquals(trace(42), trace(42));
    }

    private String trace(long seed) {
        SimNet net = new SimNet(HARSH, seed, SETTINGS);
        Peer a = net.peer("uav-a");
        Peer b = net.peer("uav-b");
        sendMany(net, a, b, 50);
        net.awaitUntil(() -> a.settled.get() == 50, 60_000);
        StringBuilder s = new StringBuilder(a.manager.sender().counters() + " | " + b.manager.sender().counters());
        a.outcomes.entrySet().stream().sorted(java.util.Map.Entry.comparingByKey()).forEach(e ->
                s.append('\n').append(e.getKey()).append(' ').append(e.getValue().result).append(" at ")
                        .append(e.getValue().settledMillis));
        return s.toString();
    }

    @Test
    void send_reportsFailedWithinTheBound_acrossAPartition_andDeliversAgainAfterHealing() {
        SimNet net = new SimNet(Net.Faults.NONE, 5, SETTINGS);
        Peer a = net.peer("uav-a");
        Peer b = net.peer("uav-b");
        net.network.partition(Set.of(a.address()), Set.of(b.address()));
        List<Long> cut = sendMany(net, a, b, 10);
        net.awaitUntil(() -> a.settled.get() == 10, SETTINGS.failureBoundMillis());
        for (long id : cut) {
            assertEquals(FailureReason.NO_ACK.name(), a.outcomes.get(id).result);
            assertEquals(0, b.times(a, id));
        }
        net.network.heal();
        List<Long> healed = sendMany(net, a, b, 10);
        net.awaitUntil(() -> a.settled.get() == 20, 1_000);
        for (long id : healed) {
            assertEquals("delivered", a.outcomes.get(id).result);
        }
    }

    @Test
    void send_reportsDelivered_whenOnlyTheAcksAreLost() {
        SimNet net = new SimNet(Net.Faults.NONE, 6, SETTINGS);
        Peer a = net.peer("uav-a");
        Peer b = net.peer("uav-b");
        // Cut b -> a only: b receives every try and acknowledges each, but no Ack arrives.
        net.network.setLink(b.address(), a.address(),
                LinkProfile.fixed(5).withLoss(1.0));
        List<Long> ids = sendMany(net, a, b, 1);
        net.scheduler.runFor(150);
        net.network.clearLinks();
        net.awaitUntil(() -> a.settled.get() == 1, SETTINGS.failureBoundMillis());
        assertEquals("delivered", a.outcomes.get(ids.get(0)).result);
        assertEquals(1, b.times(a, ids.get(0)), "retransmissions must not be delivered again");
        assertTrue(b.manager.sender().counters().duplicates() >= 2, b.manager.sender().counters().toString());
        assertEquals(b.manager.sender().counters().acksSent(),
                b.manager.sender().counters().delivered() + b.manager.sender().counters().duplicates());
    }
}
