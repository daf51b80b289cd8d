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
import net.smc.core.transport.Address;
import net.smc.sim.experiment.CpuLedger.Category;

class CpuChargeTest {
    private static final CpuCosts COSTS = new CpuCosts(60_000, 120_000, 90_000, 800, 4, 600, 3, 3_000, 500, 20, 5);
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
        CpuCharge charge = new CpuCharge(COSTS, v -> 0, CpuChargeTest::loads, IdealAuthentication.PAYLOAD_OFFSET);
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
        CpuCharge charge = new CpuCharge(COSTS, v -> 0, CpuChargeTest::loads, IdealAuthentication.PAYLOAD_OFFSET);
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
        CpuCharge charge = new CpuCharge(COSTS, v -> 0, (v, uri) -> false, IdealAuthentication.PAYLOAD_OFFSET);
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
        CpuCharge charge = new CpuCharge(COSTS, v -> 0, (v, uri) -> true, IdealAuthentication.PAYLOAD_OFFSET);
        byte[] reply = sealedPolicyReply("cdr", "policy:/roles/b0l1/mission", 63).get(0);
        charge.sendMicros(manager, vehicle, reply);
        charge.sendMicros(vehicle, manager, reply); // so that the charge knows the receiver's vehicle
        charge.receiveMicros(vehicle, manager, reply, false);
        assertFalse(charge.ledger().millisByCategory(0).containsKey(Category.DEFLATE));
        assertFalse(charge.ledger().millisByCategory(1).containsKey(Category.INFLATE));
        assertEquals(COSTS.loadNanosPerByte() * 63 / 1e6, charge.ledger().millisByCategory(1).get(Category.POLICY_LOAD),
                1e-9);
        CpuCharge longer = new CpuCharge(COSTS, v -> 0, (v, uri) -> true, IdealAuthentication.PAYLOAD_OFFSET);
        longer.sendMicros(manager, vehicle, sealedPolicyReply("cdr", "policy:/roles/b0l1/mission", 64).get(0));
        assertEquals(COSTS.deflateNanosPerByte() * 64 / 1e6, longer.ledger().millisByCategory(0).get(Category.DEFLATE),
                1e-9, "from 64 bytes the encoder deflates");
    }

    @Test
    void aSealedPolicyReplyIsChargedItsLoadingAndNamesItsSender() {
        CpuCharge charge = new CpuCharge(COSTS, v -> 0, (v, uri) -> true, IdealAuthentication.PAYLOAD_OFFSET);
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
        CpuCharge charge = new CpuCharge(COSTS, v -> 0, (v, uri) -> true, 0);
        byte[] reply = sealedPolicyReply("b0l1n0");
        charge.receiveMicros(vehicle, manager, reply, false);
        assertFalse(charge.ledger().millisByCategory(0).containsKey(Category.POLICY_LOAD));
    }

    @Test
    void firstContactIsAHandshakeOnceAndTheBusiestCellIsTheOneChargedMost() {
        CpuCharge charge = new CpuCharge(COSTS, v -> 0, (v, uri) -> true, IdealAuthentication.PAYLOAD_OFFSET);
        byte[] reply = sealedPolicyReply("b0l1n0");
        charge.receiveMicros(vehicle, manager, reply, false);
        charge.receiveMicros(vehicle, manager, reply, false);
        double handshake = charge.ledger().millisByCategory(0).get(Category.HANDSHAKE);
        assertEquals((COSTS.verifyNanos() + COSTS.agreeNanos()) / 1e6, handshake, 1e-9);
        assertEquals(0, charge.ledger().busiest());
    }

    @Test
    void aDatagramItsReceiverDropsUncheckedCostsItsDecodingOnlyAndIsNoContact() {
        byte[] reply = sealedPolicyReply("b0l1n0");
        boolean[] drops = {true};
        CpuCharge charge = new CpuCharge(COSTS, v -> 0, (v, uri) -> true, IdealAuthentication.PAYLOAD_OFFSET,
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
        assertEquals((COSTS.verifyNanos() + COSTS.agreeNanos()) / 1e6, checked.get(Category.HANDSHAKE), 1e-9,
                "the dropped datagram was no contact: the checked one is the first");
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
        CpuCharge charge = new CpuCharge(COSTS, v -> 0, (v, uri) -> true, IdealAuthentication.PAYLOAD_OFFSET,
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
        assertEquals((2 * COSTS.verifyNanos() + COSTS.signNanos() + COSTS.agreeNanos()) / 1e6,
                ledger.millisByCategory(0).get(Category.HANDSHAKE), 1e-9,
                "the held reply's check (credential and signature), then the first contact's signature and agreement");
    }

    /** A withdrawal of a discovery reply goes as the reply does: signed, no handshake, held unchecked by its receiver. */
    @Test
    void aWithdrawalToAManagerNotMetIsSignedAndStartsNoHandshake_heldItCostsItsDecoding() {
        byte[] message = new MessageEncoder().datagrams(new Envelope("b0l2n0", 8, new Withdrawal(3, "m"))).get(0);
        byte[] withdrawal = ByteBuffer.allocate(message.length + 16).putLong(43).put(message).putLong(99).array();
        CpuCharge charge = new CpuCharge(COSTS, v -> 0, (v, uri) -> true, IdealAuthentication.PAYLOAD_OFFSET,
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
