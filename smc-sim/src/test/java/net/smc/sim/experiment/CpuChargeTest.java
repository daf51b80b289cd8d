package net.smc.sim.experiment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.ByteBuffer;
import java.util.Map;

import org.junit.jupiter.api.Test;

import net.smc.core.message.Envelope;
import net.smc.core.message.MessageEncoder;
import net.smc.core.message.PolicyReply;
import net.smc.core.security.IdealAuthentication;
import net.smc.core.transport.Address;
import net.smc.sim.experiment.CpuLedger.Category;

class CpuChargeTest {
    private static final CpuCosts COSTS = new CpuCosts(60_000, 120_000, 90_000, 800, 4, 600, 3, 3_000, 500);
    private final Address manager = Address.of("10.0.0.1", 7000);
    private final Address vehicle = Address.of("10.0.0.2", 7000);

    /** A policy reply as the team simulation's network carries it: behind the seal's 8-byte counter, with an 8-byte tag after. */
    private static byte[] sealedPolicyReply(String sender) {
        byte[] message = new MessageEncoder().datagrams(new Envelope(sender, 7,
                new PolicyReply(1, "policy:/roles/b0l1/mission", 1, "x".repeat(300)))).get(0);
        return ByteBuffer.allocate(message.length + 16).putLong(42).put(message).putLong(99).array();
    }

    @Test
    void aSealedPolicyReplyIsChargedItsLoadingAndNamesItsSender() {
        CpuCharge charge = new CpuCharge(COSTS, v -> 0, IdealAuthentication.PAYLOAD_OFFSET);
        byte[] reply = sealedPolicyReply("b0l1n0");
        charge.sendMicros(manager, vehicle, reply);
        long micros = charge.receiveMicros(vehicle, manager, reply, false);
        CpuLedger ledger = charge.ledger();
        Map<Category, Double> received = ledger.millisByCategory(1);
        assertEquals(COSTS.loadNanosPerByte() * reply.length / 1e6, received.get(Category.POLICY_LOAD), 1e-9);
        assertTrue(micros >= Math.round(COSTS.loadNanosPerByte() * reply.length / 1_000), () -> micros + " us");
        assertEquals("b0l1n0", ledger.name(0));
        assertEquals(Map.of("POLICY_REPLY", 1L), ledger.receivedByKind(1));
        assertEquals(Map.of("POLICY_REPLY", 1L), ledger.sentByKind());
    }

    @Test
    void readAtTheWrongOffsetTheReplyIsNotRecognised() {
        CpuCharge charge = new CpuCharge(COSTS, v -> 0, 0);
        byte[] reply = sealedPolicyReply("b0l1n0");
        charge.receiveMicros(vehicle, manager, reply, false);
        assertFalse(charge.ledger().millisByCategory(0).containsKey(Category.POLICY_LOAD));
    }

    @Test
    void firstContactIsAHandshakeOnceAndTheBusiestCellIsTheOneChargedMost() {
        CpuCharge charge = new CpuCharge(COSTS, v -> 0, IdealAuthentication.PAYLOAD_OFFSET);
        byte[] reply = sealedPolicyReply("b0l1n0");
        charge.receiveMicros(vehicle, manager, reply, false);
        charge.receiveMicros(vehicle, manager, reply, false);
        double handshake = charge.ledger().millisByCategory(0).get(Category.HANDSHAKE);
        assertEquals((COSTS.verifyNanos() + COSTS.agreeNanos()) / 1e6, handshake, 1e-9);
        assertEquals(0, charge.ledger().busiest());
    }
}
