package net.smc.core.router;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import net.smc.core.message.Ack;
import net.smc.core.message.Envelope;
import net.smc.core.message.Heartbeat;
import net.smc.core.message.Leave;
import net.smc.core.message.Message;
import net.smc.core.message.MessageType;
import org.junit.jupiter.api.Test;

class MessageRouterTest {
    private final MessageRouter router = new MessageRouter();
    private final Recorder relay = new Recorder("relay");
    private final Recorder medic = new Recorder("medic");

    private static Envelope from(String sender, Message body) {
        return new Envelope(sender, 1, body);
    }

    private static final Message HEARTBEAT = new Heartbeat("r", 1, 0);
    private static final Message ACK = new Ack(3);

    @Test
    void registrationByType_selectsThatTypeFromEverySource() {
        router.register(relay, MessageType.HEARTBEAT);
        assertEquals(1, router.dispatch(from("uav1", HEARTBEAT)));
        assertEquals(1, router.dispatch(from("uav9", HEARTBEAT)));
        assertEquals(0, router.dispatch(from("uav1", ACK)));
        assertEquals(2, relay.received.size());
    }

    @Test
    void registrationBySource_selectsEveryTypeFromThatSource() {
        router.register(relay, "uav1");
        assertEquals(1, router.dispatch(from("uav1", HEARTBEAT)));
        assertEquals(1, router.dispatch(from("uav1", ACK)));
        assertEquals(0, router.dispatch(from("uav2", ACK)));
    }

    @Test
    void registrationByTypeAndSource_selectsOnlyThatPair() {
        router.register(relay, MessageType.ACK, "uav1");
        assertEquals(1, router.dispatch(from("uav1", ACK)));
        assertEquals(0, router.dispatch(from("uav1", HEARTBEAT)));
        assertEquals(0, router.dispatch(from("uav2", ACK)));
    }

    @Test
    void overlappingRegistrationsOfOneRole_deliverOnce() {
        router.register(relay, MessageType.HEARTBEAT);
        router.register(relay, "uav1");
        router.register(relay, MessageType.HEARTBEAT, "uav1");
        assertEquals(1, router.dispatch(from("uav1", HEARTBEAT)));
        assertEquals(1, relay.received.size());
    }

    @Test
    void deregisteringAPairInsideATypeRegistration_excludesOnlyThatPair() {
        router.register(relay, MessageType.HEARTBEAT);
        router.deregister(relay, MessageType.HEARTBEAT, "uav3");
        assertEquals(0, router.dispatch(from("uav3", HEARTBEAT)));
        assertEquals(1, router.dispatch(from("uav4", HEARTBEAT)));
        assertFalse(router.receives(relay, MessageType.HEARTBEAT, "uav3"));
    }

    @Test
    void deregisteringATypeInsideASourceRegistration_excludesThatTypeFromThatSource() {
        router.register(relay, "uav1");
        router.deregister(relay, MessageType.HEARTBEAT);
        assertEquals(0, router.dispatch(from("uav1", HEARTBEAT)));
        assertEquals(1, router.dispatch(from("uav1", ACK)));
    }

    @Test
    void registeringAgain_liftsAnExclusion() {
        router.register(relay, MessageType.HEARTBEAT);
        router.deregister(relay, MessageType.HEARTBEAT, "uav3");
        router.register(relay, MessageType.HEARTBEAT, "uav3");
        assertEquals(1, router.dispatch(from("uav3", HEARTBEAT)));
        assertEquals(0, router.sourceRows());
    }

    @Test
    void deregisteringTheAggregate_dropsItsExclusions() {
        router.register(relay, MessageType.HEARTBEAT);
        router.deregister(relay, MessageType.HEARTBEAT, "uav3");
        router.deregister(relay, MessageType.HEARTBEAT);
        assertEquals(0, router.sourceRows());
        router.register(relay, MessageType.HEARTBEAT);
        assertEquals(1, router.dispatch(from("uav3", HEARTBEAT)), "the old exclusion must not come back");
    }

    @Test
    void exclusionsOfOneRole_doNotAffectAnother() {
        router.register(relay, MessageType.HEARTBEAT);
        router.register(medic, MessageType.HEARTBEAT);
        router.deregister(relay, MessageType.HEARTBEAT, "uav3");
        assertEquals(1, router.dispatch(from("uav3", HEARTBEAT)));
        assertEquals(List.of(), relay.received);
        assertEquals(1, medic.received.size());
    }

    @Test
    void deregisteringWhatWasNeverRegistered_changesNothing() {
        router.deregister(relay, MessageType.HEARTBEAT, "uav1");
        router.deregister(relay, "uav1");
        router.deregister(relay, MessageType.ACK);
        assertEquals(0, router.subscribers());
        assertEquals(0, router.sourceRows());
    }

    @Test
    void deregisterAll_removesEveryRegistrationAndFreesTheSlot() {
        router.register(relay, MessageType.HEARTBEAT);
        router.register(relay, "uav1");
        router.deregister(relay, MessageType.ACK, "uav1");
        router.deregisterAll(relay);
        assertEquals(0, router.dispatch(from("uav1", HEARTBEAT)));
        assertEquals(0, router.subscribers());
        assertEquals(0, router.sourceRows());
    }

    @Test
    void deliveries_followTheOrderOfFirstRegistration() {
        List<String> order = new ArrayList<>();
        Subscriber a = e -> order.add("a");
        Subscriber b = e -> order.add("b");
        router.register(b, MessageType.ACK);
        router.register(a, "uav1");
        router.dispatch(from("uav1", ACK));
        assertEquals(List.of("b", "a"), order);
    }

    @Test
    void moreThan64Roles_eachReceiveOnce() {
        List<Recorder> roles = new ArrayList<>();
        for (int i = 0; i < 200; i++) {
            Recorder r = new Recorder("r" + i);
            roles.add(r);
            router.register(r, MessageType.HEARTBEAT);
            router.register(r, "uav1");
        }
        router.deregister(roles.get(130), MessageType.HEARTBEAT, "uav1");
        assertEquals(199, router.dispatch(from("uav1", HEARTBEAT)));
        for (int i = 0; i < 200; i++) {
            assertEquals(i == 130 ? 0 : 1, roles.get(i).received.size(), "role " + i);
        }
    }

    @Test
    void aThrowingSubscriber_isCountedAndOthersStillReceive() {
        router.register(e -> {
            throw new IllegalStateException("broken role");
        }, MessageType.ACK);
        router.register(relay, MessageType.ACK);
        assertEquals(2, router.dispatch(from("uav1", ACK)));
        assertEquals(1, relay.received.size());
        assertEquals(1, router.failures());
    }

    @Test
    void changesMadeWhileReceiving_applyFromTheNextPacket() {
        Subscriber[] self = new Subscriber[1];
        List<Envelope> got = new ArrayList<>();
        self[0] = e -> {
            got.add(e);
            router.deregisterAll(self[0]);
            router.register(medic, MessageType.LEAVE);
        };
        router.register(self[0], MessageType.LEAVE);
        router.register(relay, MessageType.LEAVE);
        assertEquals(2, router.dispatch(from("uav1", new Leave("x"))));
        assertEquals(1, relay.received.size());
        assertEquals(0, medic.received.size(), "medic registered during the dispatch");
        assertEquals(2, router.dispatch(from("uav1", new Leave("y"))));
        assertEquals(1, got.size());
        assertEquals(1, medic.received.size());
    }

    @Test
    void counters_countDispatchesDeliveriesAndUnroutedPackets() {
        router.register(relay, MessageType.ACK);
        router.register(medic, MessageType.ACK);
        router.dispatch(from("uav1", ACK));
        router.dispatch(from("uav1", HEARTBEAT));
        assertEquals(2, router.dispatched());
        assertEquals(2, router.deliveries());
        assertEquals(1, router.unrouted());
    }

    @Test
    void receives_answersWithoutDispatching() {
        router.register(relay, "uav1");
        assertTrue(router.receives(relay, MessageType.ACK, "uav1"));
        assertFalse(router.receives(relay, MessageType.ACK, "uav2"));
        assertFalse(router.receives(medic, MessageType.ACK, "uav1"));
        assertEquals(0, router.dispatched());
    }

    @Test
    void register_refusesANullSubscriberTypeOrSource() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> router.register(null, MessageType.ACK));
        assertEquals("subscriber is null; a registration needs a subscriber", e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> router.register(relay, (MessageType) null));
        assertEquals("type is null; a registration by type needs a message type", e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> router.register(relay, MessageType.ACK, ""));
        assertEquals("source is empty; a registration by source needs a vehicle id", e.getMessage());
        assertEquals(0, router.subscribers());
    }
}
