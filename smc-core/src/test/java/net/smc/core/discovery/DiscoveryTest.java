package net.smc.core.discovery;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import net.smc.core.capability.CapabilitySummary;
import net.smc.policy.PolicyEngine;
import net.smc.policy.api.Diagnostic;
import net.smc.policy.RunResult;
import org.junit.jupiter.api.Test;

/** root/discovery as the paper's Table I uses it. */
class DiscoveryTest {
    private final List<String> requests = new ArrayList<>();
    private final List<Diagnostic> errors = new ArrayList<>();
    private final DiscoveryObject discovery = new DiscoveryObject(CredentialCheck.sharedToken("team7"),
            (uav, role) -> requests.add(uav + " as " + role));
    private final PolicyEngine cell = PolicyEngine.builder().errors(errors::add).build();

    DiscoveryTest() {
        discovery.install(cell);
        cell.run("boot", "root/event at: \"newUAV\" put: (root/factory/event create: #(\"name\" \"uav\" \"lowLevelCap\" \"credential\")).");
    }

    private static CapabilitySummary summary(String... resources) {
        return new CapabilitySummary("uav7", new TreeSet<>(Set.of(resources)), new TreeSet<>());
    }

    /** Runs the check as Table I's condition does, on values carried by a newUAV event. */
    private Object check(Object capability, String credential) {
        RunResult r = cell.run("policy", """
                p := root/factory/ecapolicy create.
                p event: root/event/newUAV; action: [:uav :lowLevelCap :credential |
                    root at: "answer" put: (root/discovery uav: uav has: #("motion" "video") cap: lowLevelCap auth: credential)].
                p active: true.
                """);
        assertTrue(r.ok(), r.diagnostics()::toString);
        cell.raise("/event/newUAV", "newUAV", "uav7", capability, credential);
        assertTrue(errors.isEmpty(), errors::toString);
        return cell.root().get("answer");
    }

    @Test
    void capableVehicleWithTheTeamsCredential_passes() {
        assertEquals(Boolean.TRUE, check(summary("motion", "video", "infrared"), "team7"));
        assertEquals(1, discovery.accepted());
    }

    @Test
    void vehicleLackingAResource_fails() {
        assertEquals(Boolean.FALSE, check(summary("motion"), "team7"));
        assertEquals(1, discovery.lacking());
    }

    @Test
    void vehicleWithAWrongCredential_fails() {
        assertEquals(Boolean.FALSE, check(summary("motion", "video"), "stranger"));
        assertEquals(1, discovery.rejectedCredentials());
    }

    @Test
    void capabilityGivenAsAnArrayOfResourceNames_isAccepted() {
        assertEquals(Boolean.TRUE, check(List.of("video", "motion"), "team7"));
    }

    @Test
    void capabilityOfAnotherKind_isAnErrorNamingTheOperation() {
        RunResult r = cell.run("shell", "root/discovery uav: \"uav7\" has: #(\"motion\") cap: 5 auth: \"team7\".");

        assertFalse(r.ok());
        assertTrue(r.diagnostics().get(0).message().contains(
                "argument 3 of 'uav:has:cap:auth:' on Discovery must be a CapabilitySummary or an array of resource names,"
                        + " got Number"), r.diagnostics()::toString);
    }

    @Test
    void fullCapabilityRequest_isPassedToTheTeamProtocols() {
        RunResult r = cell.run("shell", "root/discovery fullCapReq: \"uav7\" role: \"surveyor\".");

        assertTrue(r.ok(), r.diagnostics()::toString);
        assertEquals(List.of("uav7 as surveyor"), requests);
        assertEquals(1, discovery.requests());
    }

    @Test
    void sharedToken_mustNotBeEmpty() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> CredentialCheck.sharedToken(""));

        assertEquals("a shared token must not be empty: an empty credential would pass", e.getMessage());
    }

    @Test
    void sharedToken_acceptsOnlyThatString() {
        CredentialCheck check = CredentialCheck.sharedToken("team7");

        assertTrue(check.accepts("uav1", "team7"));
        assertFalse(check.accepts("uav1", "team8"));
        assertFalse(check.accepts("uav1", 7));
    }

    @Test
    void holdAndResume_reachTheTeamProtocols_andACellWithoutThemSaysSo() {
        List<Boolean> held = new ArrayList<>();
        PolicyEngine recruiting = PolicyEngine.builder().errors(errors::add).build();
        new DiscoveryObject(CredentialCheck.sharedToken("team7"), new DiscoveryActions() {
            @Override
            public void requestFullCapability(String uav, String role) {
            }

            @Override
            public void holdRecruiting(boolean h) {
                held.add(h);
            }

            @Override
            public boolean recruitingHeld() {
                return !held.isEmpty() && held.get(held.size() - 1);
            }
        }).install(recruiting);
        assertTrue(recruiting.run("policy", "root/discovery hold. root at: \"h\" put: root/discovery isHeld. root/discovery resume.").ok(),
                errors::toString);
        assertEquals(List.of(true, false), held);
        assertEquals(Boolean.TRUE, recruiting.root().get("h"));

        RunResult r = cell.run("shell", "root/discovery hold.");
        assertFalse(r.ok());
        assertTrue(r.diagnostics().get(0).message().contains("cannot be held"), r.diagnostics()::toString);
    }
}
