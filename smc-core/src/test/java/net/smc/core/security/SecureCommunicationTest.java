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
