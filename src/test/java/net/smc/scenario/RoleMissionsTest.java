package net.smc.scenario;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import net.smc.core.role.Caller;
import net.smc.core.role.ExternalCallException;
import net.smc.core.role.ExternalGateway;
import net.smc.core.role.ExternalInterface;
import net.smc.core.role.Role;
import net.smc.policy.PolicyEngine;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/** Each role-mission of the repository, loaded with its authorisations into a deny-by-default cell, does its job. */
class RoleMissionsTest {
    private final PaperCell c = new PaperCell();

    @AfterEach
    void noErrors() throws Exception {
        assertTrue(c.errors.isEmpty(), c.errors::toString);
    }

    @Test
    void commander_reassignsAFailedAggregator() throws Exception {
        c.roles.load(PaperCell.role("commander"));

        c.failure("aggregator", "uav3");

        assertEquals(List.of("commander reassigns aggregator by default"), c.reassignments);
        assertEquals(List.of("Received event:UAVFailure (aggregator on uav3)"), c.out);
    }

    @Test
    void surveyor_asksDetectorCapableVehiclesToBeHazardDetectors() throws Exception {
        c.roles.load(PaperCell.role("surveyor"));

        c.newUAV("uav4", PaperCell.summary("uav4", "motion", "chemical"), PaperCell.TOKEN);

        assertEquals(List.of("uav4 for hdetector"), c.capabilityRequests);
    }

    @Test
    void surveyor_asksRadioCapableVehiclesToBeRelays() throws Exception {
        c.roles.load(PaperCell.role("surveyor"));

        c.newUAV("uav5", PaperCell.summary("uav5", "motion", "communication"), PaperCell.TOKEN);

        assertEquals(List.of("uav5 for relay"), c.capabilityRequests);
    }

    @Test
    void surveyor_reassignsTheRolesItManages_only() throws Exception {
        c.roles.load(PaperCell.role("surveyor"));

        c.failure("relay", "uav5");
        c.failure("aggregator", "uav6");

        assertEquals(List.of("surveyor reassigns relay by default"), c.reassignments);
    }

    @Test
    void aggregator_recordsHazardsThatDetectorsReportFromTheirCells() throws Exception {
        c.roles.load(Role.builder("aggregator").mission("policy:/roles/aggregator/mission")
                .authorisation("policy:/roles/aggregator/auth")
                .external(new ExternalInterface(List.of(), List.of(), List.of(), List.of("hazardDetected"))).build());
        ExternalGateway gateway = new ExternalGateway(c.roles);

        gateway.raise(new Caller("c4", "hdetector"), "aggregator", "hazardDetected", "hazardDetected", "uav4", "gas", 3, 4);

        assertEquals(List.of("Hazard gas at 3,4 reported by uav4"), c.out);
        assertEquals("[[gas, 3, 4, uav4]]", PolicyEngine.print(c.cell.resolve("root/role/aggregator/hazards")));
    }

    @Test
    void aggregator_refusesHazardReportsFromRolesNotAllowed() throws Exception {
        c.roles.load(Role.builder("aggregator").mission("policy:/roles/aggregator/mission")
                .authorisation("policy:/roles/aggregator/auth")
                .external(new ExternalInterface(List.of(), List.of(), List.of(), List.of("hazardDetected"))).build());
        ExternalGateway gateway = new ExternalGateway(c.roles);

        assertThrows(ExternalCallException.class, () -> gateway.raise(new Caller("c5", "relay"), "aggregator",
                "hazardDetected", "hazardDetected", "uav5", "gas", 3, 4));
        assertEquals("[]", PolicyEngine.print(c.cell.resolve("root/role/aggregator/hazards")));
    }

    @Test
    void hdetector_keepsTheHazardsItConfirms() throws Exception {
        c.roles.load(PaperCell.role("hdetector"));

        c.cell.raise("/event/hazardDetected", "hazardDetected", "uav4", "radiation", 7, 1);

        assertEquals(List.of("Detector confirmed radiation at 7,1"), c.out);
        assertEquals("[[radiation, 7, 1]]", PolicyEngine.print(c.cell.resolve("root/role/hdetector/found")));
    }

    @Test
    void relay_tracksWeakLinks_andForgetsRecoveredOnes() throws Exception {
        c.roles.load(PaperCell.role("relay"));

        c.cell.raise("/event/linkQuality", "linkQuality", "uav2", 0.1);
        c.cell.raise("/event/linkQuality", "linkQuality", "uav3", 0.2);
        c.cell.raise("/event/linkQuality", "linkQuality", "uav2", 0.8);

        assertEquals(List.of("Weak link to uav2: 0.1", "Weak link to uav3: 0.2"), c.out);
        assertEquals("{ uav3=\"0.2\" }", PolicyEngine.print(c.cell.resolve("root/role/relay/weakLinks")));
    }

    @Test
    void relay_isManagedByItsSurveyor_throughTheExternalInterface() throws Exception {
        c.roles.load(PaperCell.role("relay"));
        ExternalGateway gateway = new ExternalGateway(c.roles);

        Object policies = gateway.invoke(new Caller("c1", "surveyor"), "relay", "policies");
        gateway.invoke(new Caller("c1", "surveyor"), "relay", "disable:", "noteWeakLink");
        c.cell.raise("/event/linkQuality", "linkQuality", "uav2", 0.1);

        assertEquals("[noteWeakLink, forgetRecoveredLink]", PolicyEngine.print(policies));
        assertEquals(List.of(), c.out);
        assertThrows(ExternalCallException.class,
                () -> gateway.invoke(new Caller("c0", "commander"), "relay", "enable:", "noteWeakLink"));
    }
}
