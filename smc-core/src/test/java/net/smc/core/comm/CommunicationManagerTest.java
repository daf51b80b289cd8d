package net.smc.core.comm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;

import org.junit.jupiter.api.Test;

import net.smc.core.message.Ack;
import net.smc.core.message.Acks;
import net.smc.core.message.CapabilityRequest;
import net.smc.core.message.Envelope;
import net.smc.core.message.Heartbeat;
import net.smc.core.message.MessageEncoder;
import net.smc.core.message.MessageType;
import net.smc.core.message.RejectReason;
import net.smc.core.message.WireFormat;
import net.smc.core.router.MessageRouter;
import net.smc.core.transport.Address;
import net.smc.core.transport.Transport;
import net.smc.core.transport.sim.InMemoryNetwork;
import net.smc.core.transport.sim.SimulationScheduler;

/** The manager's own rules, on the in-memory network; a raw transport plays a peer that misbehaves. */
class CommunicationManagerTest {
    private final SimulationScheduler sim = new SimulationScheduler();
    private final InMemoryNetwork network = new InMemoryNetwork(sim, 1);
    private final MessageRouter router = new MessageRouter();
    private final List<Envelope> dispatched = new ArrayList<>();
    private final List<Envelope> rawReceived = new ArrayList<>();
    private final Transport raw = network.attach(Address.loopback(4009));
    private final CommunicationManager cell;

    CommunicationManagerTest() {
        for (MessageType t : MessageType.values()) {
            router.register(dispatched::add, t);
        }
        cell = CommunicationManager.builder("uav-1", network.attach(Address.loopback(4001)), sim, sim)
                .random(new SplittableRandom(1)).router(router).settings(ReliableDeliveryContract.SETTINGS).build();
        cell.start();
        var decoder = new net.smc.core.message.MessageDecoder(sim::nowMillis);
        raw.setReceiver((from, data) -> rawReceived.add(
                ((net.smc.core.message.DecodeResult.Decoded) decoder.decode(data)).envelope()));
    }

    private void inject(Envelope e) {
        for (byte[] d : new MessageEncoder().datagrams(e)) {
            raw.send(cell.localAddress(), d);
        }
    }

    @Test
    void messages_carryTheVehicleIdAndIncreasingIds() {
        cell.send(raw.localAddress(), new Heartbeat("scout", 1, 0));
        cell.send(raw.localAddress(), new CapabilityRequest("scout"), DeliveryListener.IGNORE);
        cell.broadcast(new Heartbeat("scout", 2, 0));
        sim.runFor(10);
        assertEquals(3, rawReceived.size());
        for (int i = 0; i < 3; i++) {
            assertEquals("uav-1", rawReceived.get(i).sender());
        }
        assertTrue(rawReceived.get(0).id() < rawReceived.get(1).id() && rawReceived.get(1).id() < rawReceived.get(2).id());
    }

    @Test
    void criticalMessage_isAcknowledgedEachTime_butDispatchedOnce() {
        Envelope e = new Envelope("uav-9", 77, new CapabilityRequest("scout"));
        inject(e);
        inject(e);
        inject(e);
        sim.runFor(10);
        assertEquals(1, dispatched.size());
        // The three copies arrived in one burst: one datagram acknowledges each of them.
        assertEquals(1, rawReceived.size());
        assertEquals(new Acks(List.of(77L, 77L, 77L)), rawReceived.get(0).body());
        assertEquals(2, cell.sender().counters().duplicates());
        assertEquals(3, cell.sender().counters().acksSent());
        assertEquals(1, cell.sender().counters().ackDatagrams());
        // A copy arriving later, alone, is acknowledged again, with a plain Ack.
        inject(e);
        sim.runFor(10);
        assertEquals(2, rawReceived.size());
        assertEquals(new Ack(77), rawReceived.get(1).body());
        assertEquals(1, dispatched.size());
    }

    @Test
    void aBurstOfCriticalMessages_isAcknowledgedByOneAcksDatagram_inArrivalOrder() {
        for (long id = 10; id < 15; id++) {
            inject(new Envelope("uav-9", id, new CapabilityRequest("scout")));
        }
        sim.runFor(10);
        assertEquals(5, dispatched.size());
        assertEquals(1, rawReceived.size());
        assertEquals(new Acks(List.of(10L, 11L, 12L, 13L, 14L)), rawReceived.get(0).body());
        assertEquals("uav-1", rawReceived.get(0).sender());
        assertEquals(5, cell.sender().counters().acksSent());
        assertEquals(1, cell.sender().counters().ackDatagrams());
    }

    @Test
    void aBurstOverTheBound_isAcknowledgedInDatagramsOfAtMost128Ids_theFullOnesAtOnce() {
        int n = 2 * WireFormat.MAX_ACKS + 44;
        for (long id = 1; id <= n; id++) {
            inject(new Envelope("uav-9", id, new CapabilityRequest("scout")));
        }
        while (dispatched.size() < WireFormat.MAX_ACKS - 1) {
            sim.step();
        }
        assertEquals(0, cell.sender().counters().ackDatagrams());
        sim.step();
        // the 128th id fills the batch: it goes at once, before the burst ends
        assertEquals(WireFormat.MAX_ACKS, dispatched.size());
        assertEquals(1, cell.sender().counters().ackDatagrams());
        sim.runFor(10);
        assertEquals(3, rawReceived.size());
        List<Long> all = new ArrayList<>();
        int[] sizes = new int[3];
        for (int i = 0; i < 3; i++) {
            List<Long> acked = ((Acks) rawReceived.get(i).body()).acked();
            sizes[i] = acked.size();
            all.addAll(acked);
        }
        assertEquals(List.of(WireFormat.MAX_ACKS, WireFormat.MAX_ACKS, 44), List.of(sizes[0], sizes[1], sizes[2]));
        List<Long> expected = new ArrayList<>();
        for (long id = 1; id <= n; id++) {
            expected.add(id);
        }
        assertEquals(expected, all);
    }

    @Test
    void aBurstFromTwoPeers_isAcknowledgedToEachByItsOwnDatagram() {
        Transport other = network.attach(Address.loopback(4011));
        List<Envelope> otherReceived = new ArrayList<>();
        var decoder = new net.smc.core.message.MessageDecoder(sim::nowMillis);
        other.setReceiver((from, data) -> otherReceived.add(
                ((net.smc.core.message.DecodeResult.Decoded) decoder.decode(data)).envelope()));
        inject(new Envelope("uav-9", 1, new CapabilityRequest("a")));
        for (byte[] d : new MessageEncoder().datagrams(new Envelope("uav-8", 1, new CapabilityRequest("b")))) {
            other.send(cell.localAddress(), d);
        }
        inject(new Envelope("uav-9", 2, new CapabilityRequest("c")));
        for (byte[] d : new MessageEncoder().datagrams(new Envelope("uav-8", 5, new CapabilityRequest("d")))) {
            other.send(cell.localAddress(), d);
        }
        sim.runFor(10);
        assertEquals(List.of(new Acks(List.of(1L, 2L))), rawReceived.stream().map(Envelope::body).toList());
        assertEquals(List.of(new Acks(List.of(1L, 5L))), otherReceived.stream().map(Envelope::body).toList());
    }

    @Test
    void acks_settleEachMessageItNames_andIgnoreUnknownIds() {
        List<Long> delivered = new ArrayList<>();
        DeliveryListener l = new DeliveryListener() {
            @Override
            public void delivered(long id) {
                delivered.add(id);
            }
        };
        long first = cell.send(raw.localAddress(), new CapabilityRequest("a"), l);
        long second = cell.send(raw.localAddress(), new CapabilityRequest("b"), l);
        long third = cell.send(raw.localAddress(), new CapabilityRequest("c"), l);
        inject(new Envelope("uav-9", 1, new Acks(List.of(third, 999_999L, first))));
        sim.runFor(10);
        assertEquals(List.of(third, first), delivered);
        assertEquals(1, cell.sender().outstanding());
        assertEquals(1, cell.sender().counters().unknownAcks());
        assertEquals(1, cell.counters().acksReceived());
        inject(new Envelope("uav-9", 2, new Acks(List.of(second, second))));
        sim.runFor(10);
        assertEquals(List.of(third, first, second), delivered);
        assertEquals(0, cell.sender().outstanding());
        assertEquals(2, cell.sender().counters().unknownAcks());
    }

    @Test
    void acks_fromAnotherAddress_areIgnored() {
        Transport stranger = network.attach(Address.loopback(4010));
        long id = cell.send(raw.localAddress(), new CapabilityRequest("scout"), DeliveryListener.IGNORE);
        for (byte[] d : new MessageEncoder().datagrams(new Envelope("uav-9", 1, new Acks(List.of(id, id))))) {
            stranger.send(cell.localAddress(), d);
        }
        sim.runFor(10);
        assertEquals(2, cell.sender().counters().misdirectedAcks());
        assertEquals(1, cell.sender().outstanding());
    }

    @Test
    void stop_dropsAcknowledgementsNotYetFlushed() {
        inject(new Envelope("uav-9", 3, new CapabilityRequest("scout")));
        sim.runFor(10);
        assertEquals(1, rawReceived.size());
        inject(new Envelope("uav-9", 4, new CapabilityRequest("scout")));
        inject(new Envelope("uav-9", 5, new CapabilityRequest("scout")));
        // stop between the burst's arrival and its flush
        while (cell.sender().counters().acksSent() < 3) {
            sim.step();
        }
        cell.stop();
        sim.runFor(10);
        assertEquals(1, rawReceived.size());
    }

    @Test
    void badDatagram_isCountedAndNotThrown() {
        raw.send(cell.localAddress(), new byte[] {1, 2, 3});
        sim.runFor(10);
        assertEquals(1, cell.counters().rejected());
        assertEquals(1, cell.counters().rejected(RejectReason.TRUNCATED) + cell.counters().rejected(RejectReason.BAD_MAGIC));
        assertEquals(List.of(), dispatched);
    }

    @Test
    void ack_fromAnotherAddress_isIgnored() {
        Transport stranger = network.attach(Address.loopback(4010));
        List<String> outcome = new ArrayList<>();
        long id = cell.send(raw.localAddress(), new CapabilityRequest("scout"), new DeliveryListener() {
            @Override
            public void delivered(long id) {
                outcome.add("delivered");
            }
        });
        for (byte[] d : new MessageEncoder().datagrams(new Envelope("uav-9", 1, new Ack(id)))) {
            stranger.send(cell.localAddress(), d);
        }
        sim.runFor(10);
        assertEquals(List.of(), outcome);
        assertEquals(1, cell.sender().counters().misdirectedAcks());
        assertEquals(1, cell.sender().outstanding());
    }

    @Test
    void stop_reportsOutstandingMessagesStopped_inSendOrder() {
        List<String> outcome = new ArrayList<>();
        DeliveryListener l = new DeliveryListener() {
            @Override
            public void failed(long id, FailureReason reason) {
                outcome.add(id + " " + reason);
            }
        };
        long first = cell.send(raw.localAddress(), new CapabilityRequest("a"), l);
        long second = cell.send(raw.localAddress(), new CapabilityRequest("b"), l);
        cell.stop();
        assertEquals(List.of(first + " STOPPED", second + " STOPPED"), outcome);
        var e = assertThrows(IllegalStateException.class, () -> cell.send(raw.localAddress(), new CapabilityRequest("c")));
        assertTrue(e.getMessage().contains("'uav-1' is stopped"), e.getMessage());
    }

    @Test
    void reliableSend_ofANonCriticalType_isRefused() {
        var e = assertThrows(IllegalArgumentException.class,
                () -> cell.send(raw.localAddress(), new Heartbeat("scout", 1, 0), DeliveryListener.IGNORE));
        assertTrue(e.getMessage().startsWith("HEARTBEAT to 127.0.0.1:4009 cannot be sent reliably: it is not a critical type"),
                e.getMessage());
    }

    @Test
    void broadcast_ofACriticalType_isRefused() {
        var e = assertThrows(IllegalArgumentException.class, () -> cell.broadcast(new CapabilityRequest("scout")));
        assertTrue(e.getMessage().startsWith("CAPABILITY_REQUEST cannot be broadcast: it is a critical type"),
                e.getMessage());
    }

    @Test
    void build_withoutRouterOrRandom_namesWhatIsMissing() {
        var e = assertThrows(IllegalStateException.class,
                () -> CommunicationManager.builder("uav-2", network.attach(Address.loopback(4002)), sim, sim).build());
        assertEquals("communication manager of 'uav-2' needs a random source (random(...)) and a message router"
                + " (router(...))", e.getMessage());
    }

    /**
     * The address a vehicle is answered at is the one it last sent from: it moves when the vehicle
     * sends from another address and back again, whether or not the name is the same string object,
     * and a taught address never replaces one heard.
     */
    @Test
    void theAddressOfAVehicle_followsWhereItLastSentFrom() {
        Transport other = network.attach(Address.loopback(4010));
        Transport[] order = {raw, raw, other, other, raw, other, raw};
        long id = 1;
        for (Transport t : order) {
            for (byte[] d : new MessageEncoder().datagrams(new Envelope(new String("uav-7"), id++, new Heartbeat("scout", 1, 0)))) {
                t.send(cell.localAddress(), d);
            }
            sim.runFor(10);
            assertEquals(t.localAddress(), cell.addressOf("uav-7").orElseThrow());
            cell.learnAddress("uav-7", Address.loopback(4999));
            assertEquals(t.localAddress(), cell.addressOf("uav-7").orElseThrow());
        }
        cell.learnAddress("uav-8", Address.loopback(4999));
        assertEquals(Address.loopback(4999), cell.addressOf("uav-8").orElseThrow());
    }
}
