package net.smc.scenario;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import net.smc.core.role.Loaded;
import net.smc.core.role.Role;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The paper's Table I (role assignment) and Table II (role re-assignment), as repository files,
 * loaded by the Role-Manager as the commander's role-mission into a cell that denies by default,
 * and driven by the events the protocols raise.
 */
class PaperPoliciesTest {
    private final PaperCell c = new PaperCell();
    private final Role commander = Role.builder("commander")
            .mission("policy:/roles/commander/assign", "policy:/roles/commander/reassign")
            .authorisation("policy:/roles/commander/auth")
            .manages("surveyor", "aggregator")
            .build();

    @Test
    void tablesLoad_asTheCommandersPoliciesUnderThePapersNames() throws Exception {
        Loaded loaded = c.roles.load(commander);

        assertEquals(List.of("assignSurveyor", "reAssignSurveyor"), loaded.policies());
        assertTrue(c.errors.isEmpty(), c.errors::toString);
    }

    @Test
    void tableI_capableVehicle_isAskedForItsFullCapability_asASurveyor() throws Exception {
        c.roles.load(commander);

        c.newUAV("uav7", PaperCell.summary("uav7", "motion", "video", "infrared"), PaperCell.TOKEN);

        assertEquals(List.of("uav7 for surveyor"), c.capabilityRequests);
        assertEquals(List.of("Received event:newUAV", "Checking low level capability"), c.out);
        assertTrue(c.errors.isEmpty(), c.errors::toString);
    }

    @Test
    void tableI_vehicleWithoutVideo_isNotAsked() throws Exception {
        c.roles.load(commander);

        c.newUAV("uav8", PaperCell.summary("uav8", "motion", "infrared"), PaperCell.TOKEN);

        assertEquals(List.of(), c.capabilityRequests);
        assertEquals(List.of(), c.out);
        assertTrue(c.errors.isEmpty(), c.errors::toString);
    }

    @Test
    void tableI_vehicleWithAWrongCredential_isNotAsked() throws Exception {
        c.roles.load(commander);

        c.newUAV("uav9", PaperCell.summary("uav9", "motion", "video"), "stolen");

        assertEquals(List.of(), c.capabilityRequests);
        assertEquals(List.of(), c.out);
    }

    @Test
    void tableI_withoutTheCommandersAuthorisations_isDenied() throws Exception {
        c.roles.load(Role.builder("commander").mission("policy:/roles/commander/assign").build());

        c.newUAV("uav7", PaperCell.summary("uav7", "motion", "video"), PaperCell.TOKEN);

        assertEquals(List.of(), c.capabilityRequests);
        assertEquals(1, c.errors.size(), c.errors::toString);
        assertTrue(c.errors.get(0).toString().contains("Ponder2AuthorizationException: uav:has:cap:auth:"), c.errors::toString);
    }

    @Test
    void tableII_failedSurveyor_isReassignedByTheDefaultScheme() throws Exception {
        c.roles.load(commander);

        c.failure("surveyor", "uav7");

        assertEquals(List.of("commander reassigns surveyor by default"), c.reassignments);
        assertEquals(List.of("Received event:UAVFailure"), c.out);
        assertTrue(c.errors.isEmpty(), c.errors::toString);
    }

    @ParameterizedTest
    @ValueSource(strings = {"aggregator", "relay", "hdetector"})
    void tableII_failureInAnotherRole_isNotReassigned(String role) throws Exception {
        c.roles.load(commander);

        c.failure(role, "uav7");

        assertEquals(List.of(), c.reassignments);
        assertEquals(List.of(), c.out);
        assertTrue(c.errors.isEmpty(), c.errors::toString);
    }

    @Test
    void commanderWithdrawn_nolongerAssignsOrReassigns() throws Exception {
        c.roles.load(commander);
        c.roles.withdraw("commander");

        c.newUAV("uav7", PaperCell.summary("uav7", "motion", "video"), PaperCell.TOKEN);
        c.failure("surveyor", "uav7");

        assertEquals(List.of(), c.capabilityRequests);
        assertEquals(List.of(), c.reassignments);
    }
}
