package net.smc.core.security;

import static net.smc.core.security.Team.T0;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.SplittableRandom;

import net.smc.core.comm.CommunicationManager;
import net.smc.core.message.Echo;
import net.smc.core.message.Envelope;
import net.smc.core.message.Heartbeat;
import net.smc.core.message.MessageType;
import net.smc.core.router.MessageRouter;
import net.smc.core.transport.Address;
import net.smc.core.transport.Transport;
import net.smc.core.transport.sim.InMemoryNetwork;
import net.smc.core.transport.sim.NetworkObserver;
import net.smc.core.transport.sim.SimulationScheduler;
import org.junit.jupiter.api.Test;

/**
 * A cell on an authenticating transport leaves the sender out of the headers of the types it is
 * told to, and its peers take the sender the transport proves; on a plain transport every header
 * names its sender whatever the cell is told.
 */
class SenderLeftToTransportTest {
    /** Where a message header's sender length sits (after magic, version and type). */
    private static final int SENDER_LENGTH_AT = 4;

    private final Team team = new Team(2);
    private final SimulationScheduler scheduler = new SimulationScheduler(T0);
    private final InMemoryNetwork network = new InMemoryNetwork(scheduler, 5);
    private final IdealAuthentication ideal = new IdealAuthentication(team.trust, scheduler);
    private final List<byte[]> onAir = new ArrayList<>();
    private final List<Envelope> heardByB = new ArrayList<>();

    SenderLeftToTransportTest() {
        network.addObserver(new NetworkObserver() {
            @Override
            public void delivered(long atMillis, Address from, Address to, byte[] data) {
                onAir.add(data.clone());
            }
        });
    }

    private CommunicationManager cell(String vehicle, Transport transport, List<Envelope> heard) {
        MessageRouter router = new MessageRouter();
        router.register(heard::add, MessageType.HEARTBEAT);
        router.register(heard::add, MessageType.ECHO);
        CommunicationManager c = CommunicationManager.builder(vehicle, transport, scheduler, scheduler)
                .random(new SplittableRandom(1)).router(router).senderLeftToTransport(Set.of(MessageType.HEARTBEAT)).build();
        c.start();
        return c;
    }

    @Test
    void onAnAuthenticatingTransport_theChosenTypesLeaveTheSenderOut_andArriveWithTheProvenOne() {
        Address a = Address.loopback(4001);
        Address b = Address.loopback(4002);
        CommunicationManager cellA = cell("uav-a", ideal.wrap(network.attach(a), team.identity("uav-a").credential()),
                new ArrayList<>());
        cell("uav-b", ideal.wrap(network.attach(b), team.identity("uav-b").credential()), heardByB);

        cellA.send(b, new Heartbeat("scout", 1, 0));
        cellA.send(b, new Echo(5));
        scheduler.runFor(100);

        assertEquals(2, onAir.size());
        assertEquals(0, onAir.get(0)[IdealAuthentication.PAYLOAD_OFFSET + SENDER_LENGTH_AT], "the heartbeat's header names no sender");
        assertEquals("uav-a".length(), onAir.get(1)[IdealAuthentication.PAYLOAD_OFFSET + SENDER_LENGTH_AT],
                "the echo's type was not chosen: its header names the sender");
        assertEquals(List.of("uav-a", "uav-a"), heardByB.stream().map(Envelope::sender).toList());
        assertEquals(new Heartbeat("scout", 1, 0), heardByB.get(0).body());
    }

    @Test
    void onAPlainTransport_everyHeaderNamesItsSender() {
        Address a = Address.loopback(4001);
        Address b = Address.loopback(4002);
        CommunicationManager cellA = cell("uav-a", network.attach(a), new ArrayList<>());
        cell("uav-b", network.attach(b), heardByB);

        cellA.send(b, new Heartbeat("scout", 1, 0));
        scheduler.runFor(100);

        assertEquals(1, onAir.size());
        assertEquals("uav-a".length(), onAir.get(0)[SENDER_LENGTH_AT]);
        assertEquals("uav-a", heardByB.get(0).sender());
    }
}
