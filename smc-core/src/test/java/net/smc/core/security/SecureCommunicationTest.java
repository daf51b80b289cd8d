package net.smc.core.security;

import static net.smc.core.security.Team.T0;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import net.smc.core.comm.CommunicationManager;
import net.smc.core.comm.DeliveryListener;
import net.smc.core.comm.FailureReason;
import net.smc.core.message.CapabilityRequest;
import net.smc.core.message.Envelope;
import net.smc.core.message.MessageType;
import net.smc.core.message.Roster;
import net.smc.core.transport.Transport;
import net.smc.core.router.MessageRouter;
import net.smc.core.transport.Address;
import net.smc.core.transport.sim.InMemoryNetwork;
import net.smc.core.transport.sim.SimulationScheduler;
import org.junit.jupiter.api.Test;

/**
 * The messaging layers composed as a cell uses them: a Communication-Manager (reliable delivery,
 * codec, router) over a {@link SecureTransport} over the in-memory network. Critical messages pass
 * the handshake and are delivered once; a vehicle with a credential from another authority is
 * heard by nobody.
 */
class SecureCommunicationTest {
    private final Team team = new Team(11);
    private final SimulationScheduler scheduler = new SimulationScheduler(T0);
    private final InMemoryNetwork network = new InMemoryNetwork(scheduler, 5);

    /** One vehicle: its manager and the envelopes its router handed to the application. */
    private final class Vehicle {
        final CommunicationManager comm;
        final SecureTransport secure;
        final List<Envelope> received = new ArrayList<>();

        Vehicle(SigningIdentity identity, int port) {
            secure = new SecureTransport(network.attach(Address.loopback(port)),
                    team.endpoint(identity, scheduler));
            MessageRouter router = new MessageRouter();
            router.register(received::add, MessageType.CAPABILITY_REQUEST);
            router.register(received::add, MessageType.ROSTER);
            comm = CommunicationManager.builder(identity.credential().claims().vehicleId(), secure, scheduler, scheduler)
                    .random(new SplittableRandom(port)).router(router).build();
            comm.start();
        }
    }

    @Test
    void criticalMessage_overSecureTransport_isDeliveredOnceAndAcknowledged() {
        Vehicle commander = new Vehicle(team.identity("cdr"), 5001);
        Vehicle surveyor = new Vehicle(team.identity("uav1"), 5002);
        List<String> outcome = new ArrayList<>();

        commander.comm.send(surveyor.comm.localAddress(), new CapabilityRequest("surveyor"), new DeliveryListener() {
            @Override
            public void delivered(long id) {
                outcome.add("delivered");
            }

            @Override
            public void failed(long id, FailureReason reason) {
                outcome.add("failed " + reason);
            }
        });
        scheduler.runUntilIdle(100_000);

        assertEquals(List.of("delivered"), outcome);
        assertEquals(1, surveyor.received.size());
        assertEquals("cdr", surveyor.received.get(0).sender());
        assertEquals(new CapabilityRequest("surveyor"), surveyor.received.get(0).body());
    }

    /**
     * A message whose datagram fits {@link Transport#MAX_DATAGRAM_BYTES} bare but not once the
     * authentication envelope is round it is cut into fragments that fit the secure layer's
     * capacity: rosters of every size from one datagram to several arrive whole, signed before the
     * two vehicles share a session and MAC'd after.
     */
    @Test
    void messagesOfEverySizeNearTheDatagramLimit_fitTheSecureEnvelope_andArrive() {
        Vehicle commander = new Vehicle(team.identity("cdr"), 5001);
        Vehicle backup = new Vehicle(team.identity("uav1"), 5002);
        assertTrue(commander.secure.datagramCapacity() < Transport.MAX_DATAGRAM_BYTES,
                "the secure layer leaves room for its envelope: " + commander.secure.datagramCapacity());
        List<Roster> sent = new ArrayList<>();
        for (int n = 20; n <= 80; n++) {
            List<Roster.Entry> members = new ArrayList<>();
            for (int i = 0; i < n; i++) {
                members.add(new Roster.Entry("uav" + i, "10.0.0." + (i % 250) + ":7000", "relay", i));
            }
            Roster r = new Roster("m1", n, List.of("uav1"), members);
            sent.add(r);
            commander.comm.send(backup.comm.localAddress(), r);
            scheduler.runFor(250);   // within the receiver's budget of signature checks per source
        }

        List<Long> arrived = backup.received.stream().map(e -> ((Roster) e.body()).epoch()).toList();
        assertEquals(sent.stream().map(Roster::epoch).toList(), arrived, "the rosters that arrived, by member count");
        assertEquals(sent, backup.received.stream().map(Envelope::body).toList());
        assertTrue(commander.comm.counters().datagramsSent() > sent.size(), "the larger rosters went as fragments");
    }

    @Test
    void vehicleOfAnotherAuthority_isHeardByNobody_andItsSendFails() {
        Vehicle surveyor = new Vehicle(team.identity("uav1"), 5002);
        SigningKey otherAuthority = SigningKey.generate(team.random);
        Vehicle rogue = new Vehicle(team.identity("rogue", T0 - Team.HOUR, T0 + Team.HOUR, Team.MISSION, otherAuthority),
                5003);
        List<String> outcome = new ArrayList<>();

        rogue.comm.send(surveyor.comm.localAddress(), new CapabilityRequest("surveyor"), new DeliveryListener() {
            @Override
            public void failed(long id, FailureReason reason) {
                outcome.add("failed " + reason);
            }
        });
        scheduler.runUntilIdle(100_000);

        assertTrue(surveyor.received.isEmpty(), () -> "the surveyor heard " + surveyor.received);
        assertEquals(List.of("failed NO_ACK"), outcome);
        assertTrue(surveyor.secure.endpoint().counters().rejected(Rejection.FOREIGN_AUTHORITY) > 0,
                "the surveyor counts what it refused");
    }
}
