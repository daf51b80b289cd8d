package net.smc.scenario;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import net.smc.core.capability.CapabilitySummary;
import net.smc.core.discovery.CredentialCheck;
import net.smc.core.discovery.DiscoveryObject;
import net.smc.core.role.Role;
import net.smc.core.role.RoleManager;
import net.smc.policy.api.AuthMode;
import net.smc.policy.PolicyEngine;
import net.smc.policy.api.Diagnostic;
import net.smc.policy.api.PolicyRepository;
import net.smc.policy.RunResult;

/**
 * A deployed-style cell for the paper's policies: the project's policy repository, authorisation
 * on with a default of deny after boot, the boot events, root/discovery (team token "team7") and a
 * Role-Manager, with the discovery requests and re-assignments recorded instead of sent.
 */
final class PaperCell {
    static final PolicyRepository REPOSITORY = new PolicyRepository(Path.of(System.getProperty("smc.repo.dir")));
    static final String TOKEN = "team7";
    /** Who manages whom, as in the paper's mission class (Table III). */
    static final Map<String, Set<String>> MANAGES = Map.of(
            "commander", Set.of("surveyor", "aggregator"),
            "surveyor", Set.of("hdetector", "relay"));

    final List<String> out = new ArrayList<>();
    final List<Diagnostic> errors = new ArrayList<>();
    final List<String> capabilityRequests = new ArrayList<>();
    final List<String> reassignments = new ArrayList<>();
    final PolicyEngine cell;
    final RoleManager roles;

    PaperCell() {
        cell = PolicyEngine.builder().repository(REPOSITORY).auth(AuthMode.DENY).output(out::add).errors(errors::add).build();
        RunResult boot = cell.load("policy:/boot/events");
        assertTrue(boot.ok() && boot.diagnostics().isEmpty(), () -> "boot events: " + boot.diagnostics());
        new DiscoveryObject(CredentialCheck.sharedToken(TOKEN), (uav, role) -> capabilityRequests.add(uav + " for " + role))
                .install(cell);
        cell.endBoot();
        roles = RoleManager.builder(cell)
                .reassignment((manager, role, scheme) -> reassignments.add(manager + " reassigns " + role + " by " + scheme))
                .build();
    }

    /** A role as a mission specification gives it: its mission and authorisation files by URI. */
    static Role role(String name) {
        return Role.builder(name)
                .mission("policy:/roles/" + name + "/mission")
                .authorisation("policy:/roles/" + name + "/auth")
                .manages(MANAGES.getOrDefault(name, Set.of()).toArray(String[]::new))
                .build();
    }

    static CapabilitySummary summary(String vehicle, String... resources) {
        return new CapabilitySummary(vehicle, new TreeSet<>(Set.of(resources)), new TreeSet<>());
    }

    void newUAV(String uav, CapabilitySummary capability, String credential) {
        assertTrue(cell.raise("/event/newUAV", "newUAV", uav, capability, credential), errors::toString);
    }

    void failure(String role, String uav) {
        assertTrue(cell.raise("/event/UAVFailure", "UAVFailure", role, uav, "last seen at 3,4"), errors::toString);
    }
}
