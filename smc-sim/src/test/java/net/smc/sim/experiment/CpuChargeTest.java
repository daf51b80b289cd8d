package net.smc.sim.experiment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.ByteBuffer;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Random;

import org.junit.jupiter.api.Test;

import net.smc.core.capability.CapabilitySummary;
import net.smc.core.message.DiscoveryReply;
import net.smc.core.message.Envelope;
import net.smc.core.message.MessageEncoder;
import net.smc.core.message.PolicyReply;
import net.smc.core.message.Withdrawal;
import net.smc.core.security.IdealAuthentication;
import net.smc.core.security.WireSizes;
import net.smc.core.transport.Address;
import net.smc.sim.experiment.CpuLedger.Category;

class CpuChargeTest {
    private static final CpuCosts COSTS = new CpuCosts(60_000, 120_000, 90_000, 800, 4, 600, 3, 3_000, 500, 20, 5);
    private static final String MISSION = "rescue";
    private final Address manager = Address.of("10.0.0.1", 7000);
    private final Address vehicle = Address.of("10.0.0.2", 7000);

    /** A policy reply as the team simulation's network carries it: behind the seal's 8-byte counter, with an 8-byte tag after. */
    private static byte[] sealedPolicyReply(String sender) {
        return sealedPolicyReply(sender, "policy:/roles/b0l1/mission", 300).get(0);
    }

    private static List<byte[]> sealedPolicyReply(String sender, String uri, int textLength) {
        return sealedPolicyReply(sender, uri, "x".repeat(textLength));
    }

    /** Message ids, one per reply built (the receiver tells a second copy of a message by its sender and id). */
    private static final java.util.concurrent.atomic.AtomicLong IDS = new java.util.concurrent.atomic.AtomicLong(7);

    private static List<byte[]> sealedPolicyReply(String sender, String uri, String text) {
        return sealedPolicyReply(sender, uri, 1, text);
    }

    private static List<byte[]> sealedPolicyReply(String sender, String uri, int version, String text) {
        List<byte[]> sealed = new ArrayList<>();
        for (byte[] message : new MessageEncoder().datagrams(new Envelope(sender, IDS.getAndIncrement(), new PolicyReply(1, uri,
                version, text)))) {
            sealed.add(ByteBuffer.allocate(message.length + 16).putLong(42).put(message).putLong(99).array());
        }
        return sealed;
    }

    /** Vehicle b0l1n0 loads the files of role b0l1 and nothing else. */
    private static boolean loads(String vehicle, String uri) {
        return vehicle.equals("b0l1n0") && uri.startsWith("policy:/roles/b0l1/");
    }

    /** The receiver has to have sent once for the charge to know which vehicle it is. */
    private static void introduce(CpuCharge charge, Address at, String vehicle) {
        charge.sendMicros(at, null, sealedPolicyReply(vehicle, "policy:/roles/none/mission", 10).get(0));
    }

    @Test
    void onlyThePoliciesTheReceiverLoadsAreChargedTheirLoadingAFragmentedOneOnceInFull() {
        CpuCharge charge = new CpuCharge(COSTS, MISSION, v -> 0, CpuChargeTest::loads, IdealAuthentication.PAYLOAD_OFFSET);
        introduce(charge, vehicle, "b0l1n0");
        introduce(charge, manager, "cdr");
        for (byte[] d : sealedPolicyReply("cdr", "policy:/roles/b0l2/mission", 300)) {
            charge.receiveMicros(vehicle, manager, d, false);
        }
        assertFalse(charge.ledger().millisByCategory(0).containsKey(Category.POLICY_LOAD), "a copy kept to serve a child");
        List<byte[]> fragments = sealedPolicyReply("cdr", "policy:/roles/b0l1/auth", noise(3_000));
        assertTrue(fragments.size() > 1, "fragments: " + fragments.size());
        for (byte[] d : fragments) {
            charge.receiveMicros(vehicle, manager, d, false);
        }
        Map<Category, Double> charged = charge.ledger().millisByCategory(0);
        assertEquals(COSTS.loadNanosPerByte() * 3_000 / 1e6, charged.get(Category.POLICY_LOAD), 1e-9, "per byte of text");
        assertEquals(COSTS.inflateNanosPerByte() * (300 + 3_000) / 1e6, charged.get(Category.INFLATE), 1e-9,
                "both replies were inflated, the kept copy too");
    }

    /**
     * A second copy of a reply (retransmitted after its Ack was lost, or too soon) is decoded and
     * checked, then dropped by the duplicate window: it costs no inflating and no loading.
     */
    @Test
    void aSecondCopyOfAReplyIsNeitherInflatedNorLoadedAgain() {
        CpuCharge charge = new CpuCharge(COSTS, MISSION, v -> 0, CpuChargeTest::loads, IdealAuthentication.PAYLOAD_OFFSET);
        introduce(charge, vehicle, "b0l1n0");
        introduce(charge, manager, "cdr");
        String text = "p := root/factory/ecapolicy create. p event: /event/newUAV; active: true.\n".repeat(10);
        byte[] reply = sealedPolicyReply("cdr", "policy:/roles/b0l1/mission", text).get(0);
        long first = charge.receiveMicros(vehicle, manager, reply, false);
        Map<Category, Double> once = Map.copyOf(charge.ledger().millisByCategory(0));
        long second = charge.receiveMicros(vehicle, manager, reply, false);
        Map<Category, Double> twice = charge.ledger().millisByCategory(0);
        assertEquals(COSTS.loadNanosPerByte() * text.length() / 1e6, twice.get(Category.POLICY_LOAD), 1e-9);
        assertEquals(once.get(Category.INFLATE), twice.get(Category.INFLATE), 1e-12);
        assertTrue(twice.get(Category.CODEC) > once.get(Category.CODEC), "the copy is still decoded");
        assertTrue(second < first, second + " us against " + first);
        // Another message of the same file and version (another manager's, behind an assignment the
        // vehicle refused) is stored, not loaded again; a new version is loaded.
        charge.receiveMicros(vehicle, manager, sealedPolicyReply("b0l0n1", "policy:/roles/b0l1/mission", text).get(0), false);
        assertEquals(COSTS.loadNanosPerByte() * text.length() / 1e6, charge.ledger().millisByCategory(0)
                .get(Category.POLICY_LOAD), 1e-9);
        charge.receiveMicros(vehicle, manager, sealedPolicyReply("cdr", "policy:/roles/b0l1/mission", 2, text).get(0), false);
        assertEquals(2 * COSTS.loadNanosPerByte() * text.length() / 1e6, charge.ledger().millisByCategory(0)
                .get(Category.POLICY_LOAD), 1e-9);
    }

    /** Text that deflate shrinks little (random letters): a reply of 3,000 bytes still needs fragments. */
    private static String noise(int length) {
        Random random = new Random(1);
        StringBuilder sb = new StringBuilder();
        for (int i = 0; i < length; i++) {
            sb.append((char) (random.nextInt(94) + 33));
        }
        return sb.toString();
    }

    @Test
    void aDeflatedReplyCostsItsSenderTheDeflatingAndItsReceiverTheInflating_perByteOfText() {
        CpuCharge charge = new CpuCharge(COSTS, MISSION, v -> 0, (v, uri) -> false, IdealAuthentication.PAYLOAD_OFFSET);
        String text = "p := root/factory/ecapolicy create. p event: /event/newUAV; active: true.\n".repeat(10);
        byte[] reply = sealedPolicyReply("cdr", "policy:/roles/b0l1/mission", text).get(0);
        assertTrue(reply.length < text.length() / 2, reply.length + " bytes on the wire for " + text.length());
        charge.sendMicros(manager, vehicle, reply);
        charge.receiveMicros(vehicle, manager, reply, false);
        CpuLedger ledger = charge.ledger();
        assertEquals(COSTS.deflateNanosPerByte() * text.length() / 1e6, ledger.millisByCategory(0).get(Category.DEFLATE),
                1e-9);
        assertFalse(ledger.millisByCategory(0).containsKey(Category.INFLATE));
        assertEquals(COSTS.inflateNanosPerByte() * text.length() / 1e6, ledger.millisByCategory(1).get(Category.INFLATE),
                1e-9, "inflated though not loaded");
        assertFalse(ledger.millisByCategory(1).containsKey(Category.DEFLATE));
    }

    @Test
    void aShortTextGoesAsItIs_andCostsNoCompression() {
        CpuCharge charge = new CpuCharge(COSTS, MISSION, v -> 0, (v, uri) -> true, IdealAuthentication.PAYLOAD_OFFSET);
        byte[] reply = sealedPolicyReply("cdr", "policy:/roles/b0l1/mission", 63).get(0);
        charge.sendMicros(manager, vehicle, reply);
        charge.sendMicros(vehicle, manager, reply); // so that the charge knows the receiver's vehicle
        charge.receiveMicros(vehicle, manager, reply, false);
        assertFalse(charge.ledger().millisByCategory(0).containsKey(Category.DEFLATE));
        assertFalse(charge.ledger().millisByCategory(1).containsKey(Category.INFLATE));
        assertEquals(COSTS.loadNanosPerByte() * 63 / 1e6, charge.ledger().millisByCategory(1).get(Category.POLICY_LOAD),
                1e-9);
        CpuCharge longer = new CpuCharge(COSTS, MISSION, v -> 0, (v, uri) -> true, IdealAuthentication.PAYLOAD_OFFSET);
        longer.sendMicros(manager, vehicle, sealedPolicyReply("cdr", "policy:/roles/b0l1/mission", 64).get(0));
        assertEquals(COSTS.deflateNanosPerByte() * 64 / 1e6, longer.ledger().millisByCategory(0).get(Category.DEFLATE),
                1e-9, "from 64 bytes the encoder deflates");
    }

    @Test
    void aSealedPolicyReplyIsChargedItsLoadingAndNamesItsSender() {
        CpuCharge charge = new CpuCharge(COSTS, MISSION, v -> 0, (v, uri) -> true, IdealAuthentication.PAYLOAD_OFFSET);
        byte[] reply = sealedPolicyReply("b0l1n0");
        charge.sendMicros(manager, vehicle, reply);
        charge.sendMicros(vehicle, manager, reply);
        long micros = charge.receiveMicros(vehicle, manager, reply, false);
        CpuLedger ledger = charge.ledger();
        Map<Category, Double> received = ledger.millisByCategory(1);
        assertEquals(COSTS.loadNanosPerByte() * 300 / 1e6, received.get(Category.POLICY_LOAD), 1e-9);
        assertTrue(micros >= Math.round(COSTS.loadNanosPerByte() * 300 / 1_000), () -> micros + " us");
        assertEquals("b0l1n0", ledger.name(0));
        assertEquals(Map.of("POLICY_REPLY", 1L), ledger.receivedByKind(1));
        assertEquals(Map.of("POLICY_REPLY", 2L), ledger.sentByKind());
    }

    @Test
    void readAtTheWrongOffsetTheReplyIsNotRecognised() {
        CpuCharge charge = new CpuCharge(COSTS, MISSION, v -> 0, (v, uri) -> true, 0);
        byte[] reply = sealedPolicyReply("b0l1n0");
        charge.receiveMicros(vehicle, manager, reply, false);
        assertFalse(charge.ledger().millisByCategory(0).containsKey(Category.POLICY_LOAD));
    }

    /** Unsigned, the receiver verifies a vehicle's credential once, with the first signed datagram it takes from it. */
    @Test
    void aVehiclesCredentialIsVerifiedOnce_andTheBusiestCellIsTheOneChargedMost() {
        CpuCharge charge = new CpuCharge(COSTS, MISSION, v -> 0, (v, uri) -> true, IdealAuthentication.PAYLOAD_OFFSET);
        byte[] reply = sealedPolicyReply("b0l1n0");
        charge.receiveMicros(vehicle, manager, reply, false);
        charge.receiveMicros(vehicle, manager, reply, false);
        Map<Category, Double> taken = charge.ledger().millisByCategory(0);
        assertEquals(COSTS.verifyNanos() / 1e6, taken.get(Category.HANDSHAKE), 1e-9, "the credential, once");
        assertEquals(2 * COSTS.verifyNanos() / 1e6, taken.get(Category.VERIFY), 1e-9, "no session: both signed");
        assertEquals(0, charge.ledger().busiest());
    }

    /**
     * The handshake as the security layer runs it: the first unicast goes signed with the first HELLO
     * behind it; each side answers the HELLO it takes with the next; the initiator MACs from the
     * second HELLO on, the other side from the third. The radio carries each datagram in its real
     * envelope (not the simulation's seal) and each HELLO with its sender's next datagram.
     */
    @Test
    void theHandshake_fourHellos_signedUntilEachSideHasItsSession_thenMacd() {
        CpuCharge charge = new CpuCharge(COSTS, MISSION, v -> 0, (v, uri) -> false, IdealAuthentication.PAYLOAD_OFFSET);
        byte[] fromManager = sealedPolicyReply("b0l1n0", "policy:/roles/b0l2/mission", 100).get(0);
        byte[] fromVehicle = sealedPolicyReply("b0l2n0", "policy:/roles/none/mission", 10).get(0);
        int managerPayload = fromManager.length - IdealAuthentication.SEAL_BYTES;
        int vehiclePayload = fromVehicle.length - IdealAuthentication.SEAL_BYTES;
        int hello = WireSizes.hello("b0l1n0", MISSION, "b0l2n0");
        assertEquals(hello, WireSizes.hello("b0l2n0", MISSION, "b0l1n0"), "names of the same length");
        introduce(charge, vehicle, "b0l2n0");                          // node 0: the vehicle
        long bytesBefore = charge.bytes();

        charge.sendMicros(manager, vehicle, fromManager);              // node 1: signed, HELLO 1 with it
        assertEquals(WireSizes.signed("b0l1n0", MISSION, managerPayload) + hello, charge.airBytes(manager, vehicle, fromManager));
        Map<Category, Double> m = charge.ledger().millisByCategory(1);
        assertEquals(COSTS.signNanos() / 1e6, m.get(Category.SIGN), 1e-9);
        assertEquals((COSTS.signNanos() + COSTS.agreeNanos() / 2) / 1e6, m.get(Category.HANDSHAKE), 1e-9,
                "HELLO 1 and a key pair (half of agreeNanos, which times a key pair and an agreement)");
        assertFalse(m.containsKey(Category.MAC));

        charge.receiveMicros(vehicle, manager, fromManager, false);    // takes HELLO 1, owes HELLO 2
        Map<Category, Double> v = charge.ledger().millisByCategory(0);
        assertEquals(COSTS.verifyNanos() / 1e6, v.get(Category.VERIFY), 1e-9);
        assertEquals((COSTS.verifyNanos() + COSTS.verifyNanos() + COSTS.agreeNanos() / 2 + COSTS.signNanos()) / 1e6,
                v.get(Category.HANDSHAKE), 1e-9, "the credential; HELLO 1 checked, a key pair, HELLO 2 signed");

        charge.sendMicros(vehicle, manager, fromVehicle);              // still signed (no session), HELLO 2 on the radio
        assertEquals(WireSizes.signed("b0l2n0", MISSION, vehiclePayload) + hello, charge.airBytes(vehicle, manager, fromVehicle));

        charge.receiveMicros(manager, vehicle, fromVehicle, false);    // takes HELLO 2: the initiator's session
        charge.sendMicros(manager, vehicle, fromManager);
        assertEquals(WireSizes.pairMac("b0l1n0", managerPayload) + hello, charge.airBytes(manager, vehicle, fromManager),
                "MAC'd now, HELLO 3 beside it");
        assertEquals(COSTS.signNanos() / 1e6, charge.ledger().millisByCategory(1).get(Category.SIGN), 1e-9, "no second signature");

        charge.receiveMicros(vehicle, manager, fromManager, false);    // MAC'd; takes HELLO 3: the vehicle's session
        charge.sendMicros(vehicle, manager, fromVehicle);
        assertEquals(WireSizes.pairMac("b0l2n0", vehiclePayload) + hello, charge.airBytes(vehicle, manager, fromVehicle),
                "MAC'd, HELLO 4 beside it");
        charge.receiveMicros(manager, vehicle, fromVehicle, false);    // takes HELLO 4: nothing more
        charge.sendMicros(manager, vehicle, fromManager);
        assertEquals(WireSizes.pairMac("b0l1n0", managerPayload), charge.airBytes(manager, vehicle, fromManager));

        // Each side: its own credential check of the other, two HELLOs signed, two checked besides the
        // signed datagram's, and one key pair and agreement (one agreeNanos) in all.
        double eachSide = 2 * COSTS.signNanos() + 3 * COSTS.verifyNanos() + COSTS.agreeNanos();
        assertEquals(eachSide / 1e6, charge.ledger().millisByCategory(1).get(Category.HANDSHAKE), 1e-9, "the manager");
        assertEquals(eachSide / 1e6, charge.ledger().millisByCategory(0).get(Category.HANDSHAKE), 1e-9, "the vehicle");
        assertEquals(4, charge.ledger().hellos());
        assertEquals(4L * hello, charge.ledger().helloBytes());
        assertEquals(WireSizes.signed("b0l1n0", MISSION, managerPayload) + WireSizes.signed("b0l2n0", MISSION, vehiclePayload)
                + 2 * WireSizes.pairMac("b0l1n0", managerPayload) + WireSizes.pairMac("b0l2n0", vehiclePayload) + 4L * hello,
                charge.bytes() - bytesBefore, "what the radio carried, each HELLO once");
        assertEquals(5 + 4, charge.datagrams() - 1, "five datagrams and four HELLOs, after the introduction");
        assertEquals((2 * COSTS.macNanos() + COSTS.macNanosPerByte() * (fromManager.length + fromVehicle.length)) / 1e6,
                charge.ledger().millisByCategory(0).get(Category.MAC), 1e-9,
                "the vehicle MAC'd what it took and sent under the sessions, and nothing before");
    }

    /** A broadcast goes signed with the credential, and the radio does not carry the simulation's seal. */
    @Test
    void aBroadcastIsSignedOnTheRadio_withoutTheSimulationsSeal() {
        CpuCharge charge = new CpuCharge(COSTS, MISSION, v -> 0, (v, uri) -> false, IdealAuthentication.PAYLOAD_OFFSET);
        byte[] data = sealedPolicyReply("b0l1n0", "policy:/roles/none/mission", 10).get(0);
        charge.sendMicros(manager, null, data);
        long air = WireSizes.signed("b0l1n0", MISSION, data.length - IdealAuthentication.SEAL_BYTES);
        assertEquals(air, charge.airBytes(manager, null, data));
        assertEquals(air, charge.bytes());
        assertEquals(1, charge.datagrams());
        assertEquals(0, charge.ledger().hellos(), "a broadcast starts no handshake");
        assertEquals(data.length, charge.airBytes(manager, null, data.clone()), "a datagram it was not asked about: as long as it is");
    }

    @Test
    void aDatagramItsReceiverDropsUncheckedCostsItsDecodingOnlyAndIsNoContact() {
        byte[] reply = sealedPolicyReply("b0l1n0");
        boolean[] drops = {true};
        CpuCharge charge = new CpuCharge(COSTS, MISSION, v -> 0, (v, uri) -> true, IdealAuthentication.PAYLOAD_OFFSET,
                (at, data) -> at.equals(vehicle) && data == reply && drops[0]);
        long micros = charge.receiveMicros(vehicle, manager, reply, true);
        CpuLedger ledger = charge.ledger();
        assertEquals(Map.of(Category.CODEC, (COSTS.codecNanos() + COSTS.codecNanosPerByte() * reply.length) / 1e6),
                ledger.millisByCategory(0), "no verification, no handshake, no loading");
        assertEquals(Math.round((COSTS.codecNanos() + COSTS.codecNanosPerByte() * reply.length) / 1_000), micros);
        assertEquals(Map.of("POLICY_REPLY", 1L), ledger.receivedByKind(0));
        assertEquals(Map.of("POLICY_REPLY", 1L), ledger.droppedUnverifiedByKind(0));
        drops[0] = false;
        charge.receiveMicros(vehicle, manager, reply, true);
        Map<Category, Double> checked = ledger.millisByCategory(0);
        assertEquals(COSTS.verifyNanos() / 1e6, checked.get(Category.VERIFY), 1e-9);
        assertEquals(COSTS.verifyNanos() / 1e6, checked.get(Category.HANDSHAKE), 1e-9,
                "the dropped datagram checked nothing: the credential is verified with the checked one");
        assertEquals(Map.of("POLICY_REPLY", 1L), ledger.droppedUnverifiedByKind(0));
    }

    /** A discovery reply as the team simulation's network carries it. */
    private static byte[] sealedDiscoveryReply(String sender) {
        byte[] message = new MessageEncoder().datagrams(new Envelope(sender, 7, new DiscoveryReply(3, "m",
                new CapabilitySummary(sender, new java.util.TreeSet<>(), new java.util.TreeSet<>())))).get(0);
        return ByteBuffer.allocate(message.length + 16).putLong(42).put(message).putLong(99).array();
    }

    /**
     * A discovery reply is signed and starts no handshake; its receiver, holding it unchecked, pays
     * its decoding only. The check, when the receiver makes it, is charged with its next datagram,
     * and the first contact when it then sends to the vehicle.
     */
    @Test
    void aHeldDiscoveryReplyCostsItsDecoding_itsCheckAndTheFirstContactComeOnlyWhenTheManagerContactsTheVehicle() {
        byte[] reply = sealedDiscoveryReply("b0l2n0");
        CpuCharge charge = new CpuCharge(COSTS, MISSION, v -> 0, (v, uri) -> true, IdealAuthentication.PAYLOAD_OFFSET,
                (at, data) -> false, (at, data) -> at.equals(manager) && data == reply);
        introduce(charge, manager, "b0l1n0");                    // node 0
        charge.sendMicros(vehicle, manager, reply);              // node 1
        CpuLedger ledger = charge.ledger();
        Map<Category, Double> sent = ledger.millisByCategory(1);
        assertEquals(COSTS.signNanos() / 1e6, sent.get(Category.SIGN), 1e-9, "signed");
        assertFalse(sent.containsKey(Category.HANDSHAKE), "no handshake started");
        assertFalse(sent.containsKey(Category.MAC));

        double before = ledger.totalMillis(0);
        charge.receiveMicros(manager, vehicle, reply, false);
        assertEquals((COSTS.codecNanos() + COSTS.codecNanosPerByte() * reply.length) / 1e6, ledger.totalMillis(0) - before, 1e-9,
                "held: decoding only");
        assertEquals(Map.of("DISCOVERY_REPLY", 1L), ledger.heldUnverifiedByKind(0));
        assertFalse(ledger.millisByCategory(0).containsKey(Category.HANDSHAKE));

        charge.heldChecked(manager, vehicle);
        assertEquals(1, ledger.heldCheckedCount(0));
        byte[] assignment = sealedPolicyReply("b0l1n0");
        charge.sendMicros(manager, vehicle, assignment);
        assertEquals((2 * COSTS.verifyNanos() + COSTS.signNanos() + COSTS.agreeNanos() / 2) / 1e6,
                ledger.millisByCategory(0).get(Category.HANDSHAKE), 1e-9,
                "the held reply's check (credential and signature), then HELLO 1's signature and a key pair");
    }

    /** A withdrawal of a discovery reply goes as the reply does: signed, no handshake, held unchecked by its receiver. */
    @Test
    void aWithdrawalToAManagerNotMetIsSignedAndStartsNoHandshake_heldItCostsItsDecoding() {
        byte[] message = new MessageEncoder().datagrams(new Envelope("b0l2n0", 8, new Withdrawal(3, "m"))).get(0);
        byte[] withdrawal = ByteBuffer.allocate(message.length + 16).putLong(43).put(message).putLong(99).array();
        CpuCharge charge = new CpuCharge(COSTS, MISSION, v -> 0, (v, uri) -> true, IdealAuthentication.PAYLOAD_OFFSET,
                (at, data) -> false, (at, data) -> at.equals(manager) && data == withdrawal);
        introduce(charge, manager, "b0l1n0");                    // node 0
        charge.sendMicros(vehicle, manager, withdrawal);         // node 1
        Map<Category, Double> sent = charge.ledger().millisByCategory(1);
        assertEquals(COSTS.signNanos() / 1e6, sent.get(Category.SIGN), 1e-9, "signed");
        assertFalse(sent.containsKey(Category.HANDSHAKE), "no handshake started");
        double before = charge.ledger().totalMillis(0);
        charge.receiveMicros(manager, vehicle, withdrawal, false);
        assertEquals((COSTS.codecNanos() + COSTS.codecNanosPerByte() * withdrawal.length) / 1e6,
                charge.ledger().totalMillis(0) - before, 1e-9, "held: decoding only");
        assertEquals(Map.of("WITHDRAWAL", 1L), charge.ledger().heldUnverifiedByKind(0));
    }
}
