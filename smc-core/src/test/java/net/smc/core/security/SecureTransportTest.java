package net.smc.core.security;

import static net.smc.core.security.Team.T0;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import net.smc.core.transport.Address;
import net.smc.core.transport.Transport;
import net.smc.core.transport.sim.InMemoryNetwork;
import net.smc.core.transport.sim.LinkProfile;
import net.smc.core.transport.sim.NetworkObserver;
import net.smc.core.transport.sim.SimulationScheduler;
import org.junit.jupiter.api.Test;

/**
 * Cells on the in-memory network, each behind a {@link SecureTransport}: discovery signed, sessions
 * forming by themselves, MAC'd unicast, team broadcasts; an eavesdropper's replays get nowhere.
 */
class SecureTransportTest {
    private final Team team = new Team(7);
    private final SimulationScheduler scheduler = new SimulationScheduler(T0);
    private final InMemoryNetwork network = new InMemoryNetwork(scheduler, 42);

    /** One cell: its secure transport and what its receiver heard, as "sender/protection/payload". */
    private final class Cell {
        final SecureTransport transport;
        final List<String> heard = new ArrayList<>();

        Cell(String id, int port) {
            this(team.identity(id), port);
        }

        Cell(SigningIdentity identity, int port) {
            this(identity, network.attach(Address.loopback(port)));
        }

        Cell(SigningIdentity identity, Transport raw) {
            transport = new SecureTransport(raw, team.endpoint(identity, scheduler));
            transport.setAuthenticatedReceiver((sender, from, protection, payload) -> {
                String text = new String(payload, StandardCharsets.UTF_8);
                heard.add(sender + "/" + protection + "/" + text);
                if (text.equals("DISCOVERY")) {
                    transport.send(from, bytes("REPLY from " + id()));
                }
            });
        }

        String id() {
            return transport.endpoint().id();
        }

        Address address() {
            return transport.localAddress();
        }

        SecurityCounters counters() {
            return transport.endpoint().counters();
        }
    }

    private static byte[] bytes(String s) {
        return s.getBytes(StandardCharsets.UTF_8);
    }

    private void settle() {
        scheduler.runUntilIdle(10_000);
    }

    @Test
    void twoCells_discoveryIsSigned_thenAHandshake_thenEveryUnicastIsMacd() {
        Cell commander = new Cell("cmdr", 4001);
        Cell vehicle = new Cell("uav-1", 4002);

        commander.transport.broadcast(bytes("DISCOVERY"));
        settle();

        assertEquals(List.of("cmdr/SIGNED/DISCOVERY"), vehicle.heard);
        assertEquals(List.of("uav-1/SIGNED/REPLY from uav-1"), commander.heard, "the first reply goes signed, a handshake with it");
        assertTrue(commander.transport.endpoint().hasSession("uav-1"));
        assertTrue(vehicle.transport.endpoint().hasSession("cmdr"));

        commander.transport.send(vehicle.address(), bytes("ASSIGN surveyor"));
        vehicle.transport.send(commander.address(), bytes("HB 1"));
        vehicle.transport.send(commander.address(), bytes("HB 2"));
        settle();

        assertEquals("cmdr/PAIR_MAC/ASSIGN surveyor", vehicle.heard.get(1));
        assertEquals(List.of("uav-1/PAIR_MAC/HB 1", "uav-1/PAIR_MAC/HB 2"), commander.heard.subList(1, 3));
        assertEquals(0, commander.counters().rejectedTotal() + vehicle.counters().rejectedTotal());
        assertEquals("uav-1", commander.transport.peerAt(vehicle.address()).orElseThrow());
    }

    @Test
    void threeCells_teamKeyHandedOut_thenTeamBroadcastsReachEveryone() {
        Cell commander = new Cell("cmdr", 4001);
        Cell b = new Cell("uav-b", 4002);
        Cell c = new Cell("uav-c", 4003);
        commander.transport.broadcast(bytes("DISCOVERY"));
        settle();

        commander.transport.endpoint().newTeamKey();
        commander.transport.send(b.address(), bytes("ASSIGN relay"));
        commander.transport.sendTeamKey(b.address());
        commander.transport.send(c.address(), bytes("ASSIGN surveyor"));
        commander.transport.sendTeamKey(c.address());
        settle();
        commander.transport.teamBroadcast(bytes("mission starts"));
        b.transport.teamBroadcast(bytes("sector 4 clear"));
        settle();

        assertEquals(List.of("cmdr/SIGNED/DISCOVERY", "cmdr/PAIR_MAC/ASSIGN relay", "cmdr/TEAM_MAC/mission starts"), b.heard);
        assertEquals(List.of("cmdr/SIGNED/DISCOVERY", "cmdr/PAIR_MAC/ASSIGN surveyor", "cmdr/TEAM_MAC/mission starts",
                "uav-b/TEAM_MAC/sector 4 clear"), c.heard);
        assertTrue(commander.heard.contains("uav-b/TEAM_MAC/sector 4 clear"), commander.heard.toString());
        assertEquals(1, b.counters().teamKeysInstalled());
        assertEquals(0, b.counters().rejectedTotal() + c.counters().rejectedTotal() + commander.counters().rejectedTotal());
    }

    @Test
    void eavesdroppersReplays_areRefusedAndCounted_andDeliverNothing() {
        Cell commander = new Cell("cmdr", 4001);
        Cell vehicle = new Cell("uav-1", 4002);
        Transport eavesdropper = network.attach(Address.loopback(4666));
        List<byte[]> captured = new ArrayList<>();
        network.addObserver(new NetworkObserver() {
            @Override
            public void delivered(long atMillis, Address from, Address to, byte[] data) {
                if (to.equals(vehicle.address())) {
                    captured.add(data.clone());
                }
            }
        });
        commander.transport.broadcast(bytes("DISCOVERY"));
        settle();
        commander.transport.send(vehicle.address(), bytes("ASSIGN surveyor"));
        settle();
        List<String> heardBefore = List.copyOf(vehicle.heard);
        long refusedBefore = vehicle.counters().rejectedTotal();
        List<byte[]> replays = List.copyOf(captured);

        for (byte[] datagram : replays) {
            eavesdropper.send(vehicle.address(), datagram);
        }
        settle();

        assertEquals(4, replays.size(), "discovery, the commander's two handshake steps, the assignment");
        assertEquals(heardBefore, vehicle.heard, "a replay delivers nothing");
        assertEquals(refusedBefore + replays.size(), vehicle.counters().rejectedTotal());
        assertEquals(replays.size(), vehicle.counters().rejected(Rejection.REPLAY));
    }

    @Test
    void aFloodOfForgedSignatures_isCheckedWithinABudget_andStarvesNeitherOtherSourcesNorSessions() {
        Cell commander = new Cell("cmdr", 4001);
        Cell vehicle = new Cell("uav-1", 4002);
        Cell newcomer = new Cell("uav-2", 4003);
        commander.transport.broadcast(bytes("DISCOVERY"));
        settle();
        byte[] forged = commander.transport.endpoint().wrapSigned(bytes("DISCOVERY"));
        forged[forged.length - 1] ^= 1;
        Transport attacker = network.attach(Address.loopback(4666));
        long checkedBefore = vehicle.counters().rejected(Rejection.BAD_SIGNATURE);

        for (int ms = 0; ms < 2_000; ms++) {   // 20,000 a second for 2 s, from one source
            for (int i = 0; i < 20; i++) {
                attacker.send(vehicle.address(), forged);
            }
            if (ms == 1_000) {
                newcomer.transport.send(vehicle.address(), bytes("HELLO from a stranger"));
                commander.transport.send(vehicle.address(), bytes("HB during the flood"));
            }
            scheduler.runUntil(scheduler.nowMillis() + 1);
        }
        settle();

        long checked = vehicle.counters().rejected(Rejection.BAD_SIGNATURE) - checkedBefore;
        assertTrue(checked <= 2 * 2 * SignatureBudget.PER_SOURCE_PER_SECOND, "signatures checked: " + checked);
        assertTrue(vehicle.transport.droppedOverBudget() >= 40_000 - checked - 1, "dropped unchecked: " + vehicle.transport.droppedOverBudget());
        assertTrue(vehicle.heard.contains("uav-2/SIGNED/HELLO from a stranger"), "another source keeps its budget: " + vehicle.heard);
        assertTrue(vehicle.heard.contains("cmdr/PAIR_MAC/HB during the flood"), "session traffic needs no signature: " + vehicle.heard);
    }

    @Test
    void aSignedPayloadTheReceiverWouldIgnore_isDroppedBeforeItsCheck_whileOthersAndSessionTrafficAreChecked() {
        Cell commander = new Cell("cmdr", 4001);
        Cell vehicle = new Cell("uav-1", 4002);
        commander.transport.broadcast(bytes("DISCOVERY"));
        settle();
        vehicle.transport.setUnverifiedFilter((data, offset, length) -> new String(data, offset, length, StandardCharsets.UTF_8).startsWith("IGNORED"));
        byte[] forged = commander.transport.endpoint().wrapSigned(bytes("IGNORED but forged"));
        forged[forged.length - 1] ^= 1;
        Transport attacker = network.attach(Address.loopback(4666));
        long badBefore = vehicle.counters().rejected(Rejection.BAD_SIGNATURE);

        commander.transport.broadcast(bytes("IGNORED discovery"));
        attacker.send(vehicle.address(), forged);
        commander.transport.broadcast(bytes("ANSWERED discovery"));
        commander.transport.send(vehicle.address(), bytes("IGNORED? no: under the session"));
        settle();

        assertEquals(2, vehicle.transport.droppedUnverified(), "the authentic and the forged one alike");
        assertEquals(badBefore, vehicle.counters().rejected(Rejection.BAD_SIGNATURE), "the forged signature was never checked");
        assertEquals(List.of("cmdr/SIGNED/DISCOVERY", "cmdr/SIGNED/ANSWERED discovery",
                "cmdr/PAIR_MAC/IGNORED? no: under the session"), vehicle.heard);
        assertEquals(0, commander.transport.droppedUnverified(), "no filter: everything checked");
    }

    /**
     * A reply held unchecked: the receiver reads it (nothing proven) and chooses whom to contact;
     * only a check delivers it, and only one that passes. The replying side starts no handshake, so
     * no key is agreed until the receiver contacts it.
     */
    @Test
    void aHeldReply_isReadFirst_deliveredOnlyOnceCheckedAndPassed_andStartsNoHandshake() {
        Cell commander = new Cell("cmdr", 4001);
        Cell vehicle = new Cell("uav-1", 4002);
        List<String> read = new ArrayList<>();
        commander.transport.holdUnverified((data, offset, length) -> new String(data, offset, length, StandardCharsets.UTF_8).startsWith("REPLY"),
                (from, payload) -> read.add(from + " " + new String(payload, StandardCharsets.UTF_8)));
        commander.transport.broadcast(bytes("DISCOVER (answered by hand)"));
        settle();
        vehicle.transport.sendWithoutHandshake(commander.address(), bytes("REPLY of uav-1"));
        byte[] forged = vehicle.transport.endpoint().wrapSigned(bytes("REPLY forged"));
        forged[forged.length - 1] ^= 1;
        Transport attacker = network.attach(Address.loopback(4666));
        attacker.send(commander.address(), forged);
        settle();

        assertEquals(List.of(vehicle.address() + " REPLY of uav-1", Address.loopback(4666) + " REPLY forged"), read);
        assertEquals(List.of(), commander.heard, "nothing held is delivered unchecked");
        assertEquals(2, commander.transport.heldUnverified());
        assertEquals(0, commander.counters().keysAgreed(), "the reply started no handshake");
        assertEquals(0, vehicle.counters().hellosSent());
        long badBefore = commander.counters().rejected(Rejection.BAD_SIGNATURE);

        assertTrue(commander.transport.checkHeld(Address.loopback(4666)));
        assertEquals(List.of(), commander.heard, "the forged reply fails its check");
        assertEquals(badBefore + 1, commander.counters().rejected(Rejection.BAD_SIGNATURE));
        assertTrue(commander.transport.checkHeld(vehicle.address()));
        assertEquals(List.of("uav-1/SIGNED/REPLY of uav-1"), commander.heard);
        assertFalse(commander.transport.checkHeld(vehicle.address()), "checked once: no longer held");

        commander.transport.send(vehicle.address(), bytes("ASSIGN"));   // the contact: signed, with a handshake
        settle();
        commander.transport.send(vehicle.address(), bytes("HB"));
        settle();
        assertEquals(List.of("cmdr/SIGNED/DISCOVER (answered by hand)", "cmdr/SIGNED/ASSIGN", "cmdr/PAIR_MAC/HB"), vehicle.heard);
    }

    @Test
    void restartedVehicle_getsANewSessionFromTheFirstMacItCannotRead() {
        Cell commander = new Cell("cmdr", 4001);
        SigningIdentity vehicleIdentity = team.identity("uav-1");
        Cell vehicle = new Cell(vehicleIdentity, 4002);
        commander.transport.broadcast(bytes("DISCOVERY"));
        settle();

        network.crash(vehicle.address());
        scheduler.runFor(5_000);
        Cell rebooted = new Cell(vehicleIdentity, network.restart(Address.loopback(4002)));
        commander.transport.send(rebooted.address(), bytes("HB 1"));   // under the old session: refused, and answered with a handshake
        settle();
        commander.transport.send(rebooted.address(), bytes("HB 2"));
        settle();

        assertEquals(List.of("cmdr/PAIR_MAC/HB 2"), rebooted.heard);
        assertEquals(1, rebooted.counters().rejected(Rejection.UNKNOWN_SENDER));
    }

    @Test
    void lossyDuplicatingNetwork_stillFormsSessions_andDeliversEachPayloadAtMostOnce() {
        network.setDefaultLink(LinkProfile.fixed(5).withLatency(5, 20).withLoss(0.2).withDuplication(0.3).withReorder(0.2, 30));
        Cell commander = new Cell("cmdr", 4001);
        Cell vehicle = new Cell("uav-1", 4002);
        for (int round = 0; round < 10 && !vehicle.transport.endpoint().hasSession("cmdr"); round++) {
            commander.transport.broadcast(bytes("DISCOVERY"));
            scheduler.runFor(1_000);
        }
        for (int i = 0; i < 200; i++) {
            vehicle.transport.send(commander.address(), bytes("HB " + i));
            scheduler.runFor(100);
        }
        settle();

        List<String> heartbeats = commander.heard.stream().filter(h -> h.contains("/HB ")).toList();
        assertEquals(heartbeats.size(), heartbeats.stream().distinct().count(), "no payload delivered twice");
        assertTrue(heartbeats.size() > 120, "most heartbeats arrive: " + heartbeats.size());
        assertTrue(heartbeats.stream().filter(h -> h.contains("PAIR_MAC")).count() > 100, heartbeats.toString());
        assertTrue(commander.counters().rejected(Rejection.REPLAY) > 0, "duplicates are counted as replays");
    }

    @Test
    void payloadTooLargeForItsProtection_isRefusedOnSend() {
        Cell commander = new Cell("cmdr", 4001);

        PayloadTooLargeException e = assertThrows(PayloadTooLargeException.class,
                () -> commander.transport.broadcast(new byte[Transport.MAX_DATAGRAM_BYTES - 100]));

        assertTrue(e.getMessage().startsWith("payload of 1300 bytes does not fit a SIGNED datagram"), e.getMessage());
    }

    @Test
    void secondReceiver_isRefused() {
        Cell commander = new Cell("cmdr", 4001);

        IllegalStateException e = assertThrows(IllegalStateException.class, () -> commander.transport.setReceiver((from, data) -> { }));

        assertEquals("a receiver is already set on the secure transport at 127.0.0.1:4001", e.getMessage());
        assertFalse(commander.transport.addressOf("nobody").isPresent());
    }
}
