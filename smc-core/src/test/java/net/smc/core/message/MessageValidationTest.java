package net.smc.core.message;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.math.BigDecimal;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import net.smc.core.capability.CapabilitySummary;
import org.junit.jupiter.api.Test;

/** Each record refuses what the wire cannot carry, with a message naming the field, the value and the rule. */
class MessageValidationTest {

    private static String refusal(Runnable construct) {
        return assertThrows(IllegalArgumentException.class, construct::run).getMessage();
    }

    @Test
    void envelope_refusesASenderOver64Bytes() {
        assertEquals("Envelope.sender 'ééééééééééééééééééééééééééééééééé' is 66 UTF-8 bytes; a vehicle id "
                + "must be 1 to 64 bytes", refusal(() -> new Envelope("é".repeat(33), 1, new Ack(1))));
    }

    @Test
    void envelope_refusesAnEmptySender() {
        assertEquals("Envelope.sender '' is 0 UTF-8 bytes; a vehicle id must be 1 to 64 bytes",
                refusal(() -> new Envelope("", 1, new Ack(1))));
    }

    @Test
    void envelope_refusesAMissingBody() {
        assertEquals("Envelope.body is null; it is required", refusal(() -> new Envelope("u", 1, null)));
    }

    @Test
    void names_refuseUnpairedSurrogates() {
        assertEquals("Heartbeat.role 'a\uD83D' holds an unpaired surrogate; it must be valid Unicode text",
                refusal(() -> new Heartbeat("a\uD83D", 1, 1)));
    }

    @Test
    void names_refuseNull() {
        assertEquals("Discovery.mission is null; a name must be 1 to 64 UTF-8 bytes",
                refusal(() -> new Discovery(null, "r", 0, 0)));
    }

    @Test
    void acks_refuseMoreThan128Ids() {
        List<Long> ids = new ArrayList<>(Samples.maxAcks());
        ids.add(1L);
        assertEquals("Acks.acked has 129 elements; at most 128 are allowed", refusal(() -> new Acks(ids)));
    }

    @Test
    void acks_refuseNoIds() {
        assertEquals("Acks.acked is empty; it must name 1 to 128 ids", refusal(() -> new Acks(List.of())));
    }

    @Test
    void acks_refuseANullId() {
        assertEquals("Acks.acked[1] is null; elements are required",
                refusal(() -> new Acks(Arrays.asList(1L, null))));
    }

    @Test
    void acks_refuseAMissingList() {
        assertEquals("Acks.acked is null; it is required", refusal(() -> new Acks(null)));
    }

    @Test
    void acks_keepAnImmutableCopy() {
        List<Long> ids = new ArrayList<>(List.of(1L, 2L));
        Acks acks = new Acks(ids);
        ids.add(3L);
        assertEquals(List.of(1L, 2L), acks.acked());
        assertThrows(UnsupportedOperationException.class, () -> acks.acked().add(4L));
    }

    @Test
    void heartbeat_refusesANegativeEpoch() {
        assertEquals("Heartbeat.epoch is -3; it must be 0 or more", refusal(() -> new Heartbeat("r", -3, 0)));
    }

    @Test
    void roleAssignment_refusesAnIdentityOfAnotherMission() {
        assertEquals("RoleAssignment.identity [other|1|1] is for mission 'other'; it must be for the assignment's "
                + "mission 'rescue'", refusal(() -> new RoleAssignment("rescue", "relay", new Identity("other", 1, 1),
                "uav1", List.of())));
    }

    @Test
    void roleAssignment_refusesMoreThan32Policies() {
        List<PolicyRef> refs = new ArrayList<>();
        for (int i = 0; i < 33; i++) {
            refs.add(new PolicyRef("p" + i, 1));
        }
        assertEquals("RoleAssignment.policies has 33 elements; at most 32 are allowed",
                refusal(() -> new RoleAssignment("m", "r", new Identity("m", 1, 1), "uav1", refs)));
    }

    @Test
    void policyReply_refusesATextOverItsLimit() {
        String text = Samples.ascii(WireFormat.MAX_POLICY_TEXT + 1);
        assertEquals("PolicyReply.text 'abcdefghijklmnopqrstuvwxyzabcdefghijklmn...' is 65001 UTF-8 bytes; a policy "
                + "text must be 0 to 65000 bytes", refusal(() -> new PolicyReply(1, "u", 1, text)));
    }

    @Test
    void values_refuseAJavaTypeThatIsNotAPonderTalkValue() {
        assertEquals("RoleEvent.values[1] is a java.lang.Integer (7); a PonderTalk value must be a String, "
                + "BigDecimal, Boolean, null or a List of those",
                refusal(() -> new RoleEvent("r", "e", List.of("x", 7))));
    }

    @Test
    void values_refuseListsNestedDeeperThanFour() {
        assertEquals("Invocation.args[0][0][0][0][0] is a list nested 5 deep; PonderTalk values nest at most 4 deep",
                refusal(() -> new Invocation("r", "o", List.of(Samples.nested(5, "x")))));
    }

    /** Values that fit are let through by a check that names nothing: it must draw every line where the named one does. */
    @Test
    @SuppressWarnings("unchecked")
    void values_nestedToTheLimit_areAcceptedAndCopiedAtEveryLevel_asListsAndAsAValue_oneDeeperIsRefused() {
        List<Object> limit = Samples.nested(4, "x");
        Invocation call = new Invocation("r", "o", List.of(limit));
        InvocationResult result = InvocationResult.ok(1, limit);
        assertEquals(List.of(limit), call.args());
        assertEquals(limit, result.value());
        List<?> innermostOfCall = (List<?>) ((List<?>) ((List<?>) ((List<?>) call.args().get(0)).get(0)).get(0)).get(0);
        assertEquals(List.of("x"), innermostOfCall);
        assertThrows(UnsupportedOperationException.class, () -> ((List<Object>) innermostOfCall).add("y"));
        List<Object> innermost = (List<Object>) ((List<?>) ((List<?>) limit.get(0)).get(0)).get(0);
        innermost.set(0, "changed");
        assertEquals("x", ((List<?>) ((List<?>) ((List<?>) ((List<?>) result.value()).get(0)).get(0)).get(0)).get(0),
                "a deep copy");
        assertEquals("InvocationResult.value[0][0][0][0] is a list nested 5 deep; PonderTalk values nest at most 4 deep",
                refusal(() -> InvocationResult.ok(1, Samples.nested(5, "x"))));
    }

    @Test
    void values_refuseAStringThatIsNoUnicodeTextOrTooLong_deepInAList() {
        assertEquals("RoleEvent.values[1][0] '\ud800' holds an unpaired surrogate; it must be valid Unicode text",
                refusal(() -> new RoleEvent("r", "e", List.of("a", List.of("\ud800")))));
        String longest = Samples.ascii(WireFormat.MAX_VALUE_STRING);
        assertEquals(List.of(List.of(longest)), new RoleEvent("r", "e", List.of(List.of(longest))).values());
        assertTrue(refusal(() -> InvocationResult.ok(1, List.of(List.of(longest + "z")))).startsWith(
                "InvocationResult.value[0][0] '"), "named down to the element");
    }

    @Test
    void values_refuseANumberOver64Bytes() {
        BigDecimal huge = new BigDecimal(java.math.BigInteger.TWO.pow(512));
        assertEquals("RoleEvent.values[0] 13407807929942597099... needs 65 bytes; a number must fit 64 bytes "
                + "(about 150 digits)", refusal(() -> new RoleEvent("r", "e", List.of(huge))));
    }

    @Test
    void values_acceptNilElementsAndAreCopied() {
        List<Object> values = new ArrayList<>(Arrays.asList("a", null));
        RoleEvent e = new RoleEvent("r", "e", values);
        values.set(0, "changed");
        assertEquals(Arrays.asList("a", null), e.values());
        assertThrows(UnsupportedOperationException.class, () -> e.values().add("x"));
    }

    @Test
    void invocationResult_refusesAnErrorOnSuccess() {
        assertEquals("InvocationResult.error is 'oops' but ok is true; a successful result has a null error",
                refusal(() -> new InvocationResult(1, true, null, "oops")));
    }

    @Test
    void invocationResult_refusesAFailureWithoutError() {
        assertEquals("InvocationResult.error '' is 0 UTF-8 bytes; the error of a failed result must be 1 to 255 bytes",
                refusal(() -> InvocationResult.failed(1, "")));
    }

    @Test
    void discoveryReply_refusesAHeldRoleOver64Bytes() {
        String refusal = refusal(() -> new DiscoveryReply(1, "m", "r".repeat(65), new CapabilitySummary("uav1",
                new java.util.TreeSet<>(), new java.util.TreeSet<>())));
        assertEquals(true, refusal.startsWith("DiscoveryReply.holds 'rrrr") && refusal.endsWith(
                "' is 65 UTF-8 bytes; the role held (empty when free) must be 0 to 64 bytes"), refusal);
    }

    @Test
    void discoveryReply_refusesASummaryWithTooManyResources() {
        java.util.TreeSet<String> resources = new java.util.TreeSet<>();
        for (int i = 0; i < 65; i++) {
            resources.add("r" + i);
        }
        assertEquals("DiscoveryReply.summary.resources has 65 elements; at most 64 are allowed",
                refusal(() -> new DiscoveryReply(1, "m", new CapabilitySummary("uav1", resources, resources))));
    }

    @Test
    void capabilityReply_refusesAnEmptyTaskName() {
        assertEquals("CapabilityReply.description.tasks[0].task '' is 0 UTF-8 bytes; a name must be 1 to 64 bytes",
                refusal(() -> new CapabilityReply(1, net.smc.core.capability.CapabilityDescription.of("uav1",
                        java.util.Set.of(), List.of(net.smc.core.capability.TaskDescription.empty(""))))));
    }

    @Test
    void capabilityReply_namesTheDeepFieldThatBreaksARule() {
        String long65 = "x".repeat(65);
        var op = new net.smc.core.capability.OperationDescription("go", List.of("int", long65));
        var attribute = new net.smc.core.capability.EventDescription.Attribute("at", "");
        var event = new net.smc.core.capability.EventDescription("done", List.of(attribute));
        var withBadArgument = new net.smc.core.capability.TaskDescription("move", List.of(op), List.of());
        var withBadAttribute = new net.smc.core.capability.TaskDescription("move", List.of(), List.of(event));
        var good = net.smc.core.capability.TaskDescription.empty("idle");
        assertEquals("CapabilityReply.description.tasks[1].operations[0].argumentTypes[1] '" + "x".repeat(40)
                        + "...' is 65 UTF-8 bytes; a name must be 1 to 64 bytes",
                refusal(() -> new CapabilityReply(1, net.smc.core.capability.CapabilityDescription.of("uav1",
                        java.util.Set.of(), List.of(good, withBadArgument)))));
        assertEquals("CapabilityReply.description.tasks[0].events[0].attributes[0].type '' is 0 UTF-8 bytes; a name must be 1 to 64 bytes",
                refusal(() -> new CapabilityReply(1, net.smc.core.capability.CapabilityDescription.of("uav1",
                        java.util.Set.of(), List.of(withBadAttribute)))));
        assertEquals("CapabilityReply.description.resources[1] '" + "x".repeat(40)
                        + "...' is 65 UTF-8 bytes; a name must be 1 to 64 bytes",
                refusal(() -> new CapabilityReply(1, net.smc.core.capability.CapabilityDescription.of("uav1",
                        java.util.Set.of("a", long65), List.of(good)))));
    }

    @Test
    void discoveryReply_refusesAnOverlongVehicleName() {
        assertEquals("DiscoveryReply.summary.vehicle '" + "v".repeat(40) + "...' is 65 UTF-8 bytes; a name must be 1 to 64 bytes",
                refusal(() -> new DiscoveryReply(1, "m", new CapabilitySummary("v".repeat(65),
                        new java.util.TreeSet<>(), new java.util.TreeSet<>()))));
    }

    @Test
    void status_refusesANegativeTeamSize() {
        assertEquals("Status.teamSize is -1; it must be 0 or more",
                refusal(() -> new Status("m", new Identity("m", 0, 0), "uav1", 0, -1)));
    }
}
