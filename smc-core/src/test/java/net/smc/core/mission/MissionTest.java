package net.smc.core.mission;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import java.util.Optional;
import net.smc.core.capability.CapabilityRequirement;
import org.junit.jupiter.api.Test;

/** The checks of a mission built in code (no files, so no positions: the messages name the role). */
class MissionTest {

    static MissionRole role(String name, int minimal, int optimal, List<String> manages, String primary) {
        return new MissionRole(name, minimal, optimal, manages, CapabilityRequirement.none(), Optional.ofNullable(primary),
                List.of("policy:/roles/" + name + "/mission"), List.of());
    }

    static Mission mission(List<MissionRole> roles, Colocation colocation) {
        return new Mission("Test", "test", roles, colocation, Map.of());
    }

    private static final Colocation RELAY_BESIDE_SURVEYOR =
            new Colocation(List.of(new Colocation.Parallel("relay", List.of("surveyor"))), List.of());

    @Test
    void rolesFormingATreeUnderTheCommander_makeAMission() {
        Mission mission = mission(List.of(role("commander", 1, 1, List.of("surveyor"), null),
                role("surveyor", 1, 2, List.of("relay"), null), role("relay", 1, 1, List.of(), "surveyor")),
                RELAY_BESIDE_SURVEYOR);

        assertEquals(List.of("commander", "surveyor", "relay"), mission.tree().breadthFirst());
        assertTrue(mission.allowsOnOneVehicle(List.of("surveyor", "relay")));
    }

    @Test
    void missionWithoutCommander_isRejected() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> mission(List.of(role("surveyor", 1, 1, List.of(), null)), Colocation.none()));

        assertEquals("no role 'commander'; the management tree is rooted at the commander", e.getMessage());
    }

    @Test
    void roleWithTwoManagers_isRejected() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> mission(List.of(
                role("commander", 1, 1, List.of("surveyor", "relay"), null),
                role("surveyor", 1, 1, List.of("relay"), null), role("relay", 1, 1, List.of(), null)), Colocation.none()));

        assertEquals("role 'relay' is managed by both 'commander' and 'surveyor'; each role has one manager", e.getMessage());
    }

    @Test
    void roleUnreachableFromTheCommander_isRejected() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> mission(List.of(
                role("commander", 1, 1, List.of(), null), role("a", 1, 1, List.of("b"), null),
                role("b", 1, 1, List.of("a"), null)), Colocation.none()));

        assertEquals("role 'a' cannot be reached from the commander; the management relation must be a tree rooted "
                + "at the commander", e.getMessage());
    }

    @Test
    void secondaryRoleItsPrimaryDoesNotManage_isRejected() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> mission(List.of(
                role("commander", 1, 1, List.of("surveyor", "relay"), null), role("surveyor", 1, 1, List.of(), null),
                role("relay", 1, 1, List.of(), "surveyor")), RELAY_BESIDE_SURVEYOR));

        assertEquals("role 'relay' is secondary to 'surveyor', which does not manage it; a primary role manages its "
                + "secondary roles", e.getMessage());
    }

    @Test
    void secondaryRoleNoRuleLetsBesideItsPrimary_isRejected() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> mission(List.of(
                role("commander", 1, 1, List.of("surveyor"), null), role("surveyor", 1, 1, List.of("relay"), null),
                role("relay", 1, 1, List.of(), "surveyor")), Colocation.none()));

        assertEquals("role 'relay' is secondary to 'surveyor', but no parallel or exclusive rule lets them share a vehicle",
                e.getMessage());
    }

    @Test
    void colocationRuleNamingAnUnknownRole_isRejected() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> mission(List.of(
                role("commander", 1, 1, List.of(), null)),
                new Colocation(List.of(), List.of(new Colocation.Exclusive(List.of("commander", "pilot"))))));

        assertEquals("a colocation rule names unknown role 'pilot'", e.getMessage());
    }

    @Test
    void roleWithMinimalAboveOptimal_isRejected() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> role("relay", 3, 2, List.of(), null));

        assertEquals("role 'relay' has minimal 3 and optimal 2; they must satisfy 0 <= minimal <= optimal and optimal >= 1",
                e.getMessage());
    }

    @Test
    void allowsOnOneVehicle_needsOnePrimaryAndItsSecondaries() {
        Colocation rules = new Colocation(List.of(new Colocation.Parallel("relay", List.of("surveyor", "hdetector"))),
                List.of(new Colocation.Exclusive(List.of("surveyor", "hdetector"))));
        Mission mission = mission(List.of(role("commander", 1, 1, List.of("surveyor", "aggregator"), null),
                role("surveyor", 2, 2, List.of("hdetector", "relay"), null), role("aggregator", 1, 1, List.of(), null),
                role("hdetector", 2, 2, List.of(), "surveyor"), role("relay", 2, 2, List.of(), "surveyor")), rules);

        assertTrue(mission.allowsOnOneVehicle(List.of("surveyor", "hdetector", "relay")));
        assertTrue(mission.allowsOnOneVehicle(List.of("aggregator")));
        assertFalse(mission.allowsOnOneVehicle(List.of("commander", "aggregator")), "two primaries");
        assertFalse(mission.allowsOnOneVehicle(List.of("hdetector", "relay")), "secondaries without their primary");
        assertFalse(mission.allowsOnOneVehicle(List.of("surveyor", "surveyor")), "one role twice");
        assertFalse(mission.allowsOnOneVehicle(List.of("pilot")), "unknown role");
    }
}
