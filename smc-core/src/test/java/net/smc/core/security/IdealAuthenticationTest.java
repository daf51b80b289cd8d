package net.smc.core.security;

import static net.smc.core.security.Team.T0;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;

import net.smc.core.transport.Address;
import net.smc.core.transport.Transport;
import net.smc.core.transport.sim.InMemoryNetwork;
import net.smc.core.transport.sim.NetworkObserver;
import net.smc.core.transport.sim.SimulationScheduler;
import org.junit.jupiter.api.Test;

/**
 * The ideal model refuses what the real {@link SecureTransport} refuses, against an adversary that
 * can put any bytes on the in-memory network under any source address.
 */
class IdealAuthenticationTest {
    private final Team team = new Team(3);
    private final SimulationScheduler scheduler = new SimulationScheduler(T0);
    private final InMemoryNetwork network = new InMemoryNetwork(scheduler, 5);
    private final IdealAuthentication ideal = new IdealAuthentication(team.trust, scheduler);
    private final Address a = Address.loopback(4001);
    private final Address b = Address.loopback(4002);
    private final List<String> heardByB = new ArrayList<>();
    private final List<byte[]> onAir = new ArrayList<>();
    private IdealAuthentication.Endpoint endpointA;

    private IdealAuthentication.Endpoint endpointB;

    IdealAuthenticationTest() {
        endpointA = ideal.wrap(network.attach(a), team.identity("uav-a").credential());
        endpointB = ideal.wrap(network.attach(b), team.identity("uav-b").credential());
        endpointB.setAuthenticatedReceiver((sender, from, protection, payload) ->
                heardByB.add(sender + ":" + new String(payload, StandardCharsets.UTF_8)));
        endpointA.setReceiver((from, data) -> { });
        network.addObserver(new NetworkObserver() {
            @Override
            public void delivered(long atMillis, Address from, Address to, byte[] data) {
                onAir.add(data.clone());
            }
        });
    }

    private void sendAndDeliver(String text) {
        endpointA.send(b, text.getBytes(StandardCharsets.UTF_8));
        scheduler.runFor(100);
    }

    @Test
    void authenticTraffic_isDeliveredWithItsSender() {
        sendAndDeliver("hello");
        endpointA.broadcast("all".getBytes(StandardCharsets.UTF_8));
        scheduler.runFor(100);
        assertEquals(List.of("uav-a:hello", "uav-a:all"), heardByB);
    }

    @Test
    void aPayloadTheReceiverWouldIgnore_isDroppedBeforeItsChecks_andTheCpuModelCanAskSo() {
        endpointB.setUnverifiedFilter((data, offset, length) -> new String(data, offset, length, StandardCharsets.UTF_8).startsWith("IGNORED"));
        endpointA.broadcast("IGNORED discovery".getBytes(StandardCharsets.UTF_8));
        sendAndDeliver("answered");
        assertEquals(List.of("uav-a:answered"), heardByB);
        assertEquals(1, ideal.ignoredUnverified());
        assertTrue(ideal.dropsUnverified(b, onAir.get(0)), "what the endpoint at b drops, read from the sealed datagram");
        assertFalse(ideal.dropsUnverified(b, onAir.get(1)));
        assertFalse(ideal.dropsUnverified(a, onAir.get(0)), "a has no filter");
        assertFalse(ideal.dropsUnverified(Address.loopback(4999), onAir.get(0)), "no endpoint there");
    }

    /** As the real transport: a held payload is read first, delivered only once checked, and only if it passes. */
    @Test
    void aHeldPayload_isReadFirst_deliveredOnlyOnceChecked_andTheCpuModelHearsOfTheCheck() {
        List<String> read = new ArrayList<>();
        List<String> checks = new ArrayList<>();
        ideal.onHeldChecked((at, from) -> checks.add(at + "<" + from));
        endpointB.holdUnverified((data, offset, length) -> new String(data, offset, length, StandardCharsets.UTF_8).startsWith("REPLY"),
                (from, payload) -> read.add(from + " " + new String(payload, StandardCharsets.UTF_8)));
        endpointA.sendWithoutHandshake(b, "REPLY of uav-a".getBytes(StandardCharsets.UTF_8));
        sendAndDeliver("other");
        Address forger = Address.loopback(4666);
        byte[] forged = onAir.get(0).clone();
        forged[forged.length - 1] ^= 1;
        network.inject(forger, b, forged, 0);
        scheduler.runFor(100);

        assertEquals(List.of(a + " REPLY of uav-a", forger + " REPLY of uav-a"), read);
        assertEquals(List.of("uav-a:other"), heardByB, "the held payload is not delivered unchecked");
        assertTrue(ideal.holdsUnverified(b, onAir.get(0)), "what the CPU model asks, read from the sealed datagram");
        assertFalse(ideal.holdsUnverified(b, onAir.get(1)));
        assertFalse(ideal.holdsUnverified(a, onAir.get(0)), "a holds nothing");

        assertTrue(endpointB.checkHeld(forger));
        assertEquals(List.of("uav-a:other"), heardByB, "the forgery fails its check");
        assertTrue(endpointB.checkHeld(a));
        assertEquals(List.of("uav-a:other", "uav-a:REPLY of uav-a"), heardByB);
        assertFalse(endpointB.checkHeld(a), "no longer held");
        assertEquals(List.of(b + "<" + forger, b + "<" + a), checks);
        assertEquals(2, ideal.heldUnverified());
    }

    /** The seal's 16 bytes come off the capacity the layer above fills: a full datagram fits once sealed. */
    @Test
    void aDatagramFillingTheEndpointsCapacity_isSealedAndDelivered() {
        int capacity = endpointA.datagramCapacity();
        assertEquals(Transport.MAX_DATAGRAM_BYTES - IdealAuthentication.SEAL_BYTES, capacity);
        sendAndDeliver("x".repeat(capacity));
        assertEquals(List.of("uav-a:" + "x".repeat(capacity)), heardByB);
    }

    @Test
    void aReplay_isRefused_atOnceAndLater() {
        sendAndDeliver("assign");
        network.inject(a, b, onAir.get(0), 0);
        network.inject(a, b, onAir.get(0), 10_000);
        scheduler.runFor(11_000);
        assertEquals(List.of("uav-a:assign"), heardByB);
        assertEquals(2, ideal.replayed());
    }

    @Test
    void reorderedTraffic_passes_butEachDatagramOnce() {
        sendAndDeliver("one");
        sendAndDeliver("two");
        heardByB.clear();
        onAir.clear();
        endpointA.send(b, "three".getBytes(StandardCharsets.UTF_8));
        endpointA.send(b, "four".getBytes(StandardCharsets.UTF_8));
        scheduler.runFor(100);
        network.inject(a, b, onAir.get(1), 0);
        network.inject(a, b, onAir.get(0), 1);
        scheduler.runFor(100);
        assertEquals(List.of("uav-a:three", "uav-a:four"), heardByB);
    }

    @Test
    void aFlippedBit_isRefused() {
        sendAndDeliver("role");
        for (int bit = 0; bit < onAir.get(0).length * 8; bit++) {
            byte[] flipped = onAir.get(0).clone();
            flipped[bit / 8] ^= (byte) (1 << (bit % 8));
            network.inject(a, b, flipped, 0);
        }
        scheduler.runFor(100);
        assertEquals(List.of("uav-a:role"), heardByB);
        assertEquals(onAir.get(0).length * 8, ideal.tampered() + ideal.replayed());
    }

    @Test
    void aStaleDatagram_isRefused_evenByAReceiverThatForgotItsCounters() {
        sendAndDeliver("old");
        byte[] old = onAir.get(0);
        network.crash(b);
        IdealAuthentication.Endpoint restarted = ideal.wrap(network.restart(b), team.identity("uav-b").credential());
        List<String> heard = new ArrayList<>();
        restarted.setAuthenticatedReceiver((sender, from, protection, payload) -> heard.add(sender));
        network.inject(a, b, old, 0);
        network.inject(a, b, old, 31_000);
        scheduler.runFor(32_000);
        assertEquals(List.of(), heard, "a unicast to the earlier incarnation, at once and after 31 s");
    }

    @Test
    void aDatagramUnderAnotherSourceAddress_orForged_isRefused() {
        Address c = Address.loopback(4003);
        ideal.wrap(network.attach(c), team.identity("uav-c").credential());
        sendAndDeliver("mine");
        network.inject(c, b, onAir.get(0), 0);
        network.inject(a, b, new byte[40], 0);
        network.inject(a, b, new byte[3], 0);
        scheduler.runFor(100);
        assertEquals(List.of("uav-a:mine"), heardByB);
        assertEquals(3, ideal.tampered());
    }

    @Test
    void eachSenderHasItsOwnReplayWindow_andARestartedSenderIsHeardAgain() {
        Address c = Address.loopback(4003);
        IdealAuthentication.Endpoint endpointC = ideal.wrap(network.attach(c), team.identity("uav-c").credential());
        endpointC.send(b, "c1".getBytes(StandardCharsets.UTF_8));
        scheduler.runFor(100);
        byte[] fromC = onAir.get(0);
        sendAndDeliver("a1");
        network.inject(c, b, fromC, 0);
        sendAndDeliver("a2");
        network.crash(a);
        IdealAuthentication.Endpoint again = ideal.wrap(network.restart(a), team.identity("uav-a").credential());
        again.send(b, "a3".getBytes(StandardCharsets.UTF_8));
        endpointB.send(a, "to the new a".getBytes(StandardCharsets.UTF_8));
        List<String> heardByNewA = new ArrayList<>();
        again.setAuthenticatedReceiver((sender, from, protection, payload) -> heardByNewA.add(sender));
        scheduler.runFor(100);
        assertEquals(List.of("uav-c:c1", "uav-a:a1", "uav-a:a2", "uav-a:a3"), heardByB);
        assertEquals(1, ideal.replayed(), "c's datagram again");
        assertEquals(List.of("uav-b"), heardByNewA, "a unicast sealed for the current incarnation");
    }
}
