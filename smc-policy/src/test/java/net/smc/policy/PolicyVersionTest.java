package net.smc.policy;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;

import net.smc.policy.api.AuthMode;
import net.smc.policy.api.PolicyHandle;
import org.junit.jupiter.api.Test;

/**
 * {@link PolicyEngine#policyVersion()}: grows on every kind of change that can change what the
 * policies decide, and stays put while the policies only run.
 */
class PolicyVersionTest {
    private static final String EVENT_AND_POLICY = """
            root/event at: "seen" put: (root/factory/event create: #("uav")).
            root at: "p" put: root/factory/ecapolicy create.
            root/p event: root/event/seen; action: [:uav | root print: uav].
            """;

    private final List<String> printed = new ArrayList<>();
    private final List<String> errors = new ArrayList<>();

    private PolicyEngine cell(AuthMode mode) {
        return PolicyEngine.builder().auth(mode).output(printed::add).errors(d -> errors.add(d.toString())).build();
    }

    /** Runs {@code text} and returns by how much the version grew; fails on any error. */
    private long growth(PolicyEngine cell, String text) {
        long before = cell.policyVersion();
        cell.run("change.p2", text);
        assertEquals(List.of(), errors, "errors in: " + text);
        return cell.policyVersion() - before;
    }

    @Test
    void raisingEventsAndRunningPoliciesLeaveTheVersionAlone() {
        PolicyEngine cell = cell(AuthMode.OFF);
        cell.run("boot.p2", EVENT_AND_POLICY + "root/p active: true.");
        long version = cell.policyVersion();
        for (int i = 0; i < 5; i++) {
            cell.raise("root/event/seen", "uav" + i);
        }
        assertEquals(5, printed.size(), "the policy ran");
        assertEquals(version, cell.policyVersion());
        assertEquals(0, growth(cell, "root print: 1 + 2."));
    }

    @Test
    void loadingAPolicyBumpsTheVersion() {
        PolicyEngine cell = cell(AuthMode.OFF);
        assertTrue(growth(cell, EVENT_AND_POLICY) > 0, "created and configured");
        assertTrue(growth(cell, """
                q := root/factory/ecapolicy create.
                """) > 0, "created");
    }

    @Test
    void enablingAndDisablingBumpTheVersion_settingTheSameStateDoesNot() {
        PolicyEngine cell = cell(AuthMode.OFF);
        cell.run("boot.p2", EVENT_AND_POLICY);
        assertTrue(growth(cell, "root/p active: true.") > 0, "enabled");
        assertEquals(0, growth(cell, "root/p active: true."), "already enabled");
        assertTrue(growth(cell, "root/p active: false.") > 0, "disabled");
        assertEquals(0, growth(cell, "root/p active: false."), "already disabled");
    }

    @Test
    void changingAConditionOrActionOrEventBumpsTheVersion() {
        PolicyEngine cell = cell(AuthMode.OFF);
        cell.run("boot.p2", EVENT_AND_POLICY + "root/p active: true.");
        assertTrue(growth(cell, "root/p condition: [:uav | false].") > 0, "condition");
        assertTrue(growth(cell, "root/p action: [:uav | root print: 0].") > 0, "action");
        assertTrue(growth(cell, "root/p eaction: [:e | root print: 0].") > 0, "whole-event action");
        assertTrue(growth(cell, "root/p event: root/event/seen.") > 0, "event");
    }

    @Test
    void withdrawingAPolicyBumpsTheVersion() {
        PolicyEngine cell = cell(AuthMode.OFF);
        cell.run("boot.p2", EVENT_AND_POLICY + "root/p active: true.");
        PolicyHandle policy = (PolicyHandle) cell.resolve("root/p");
        long before = cell.policyVersion();
        policy.retire();
        assertTrue(cell.policyVersion() > before, "retired");
        assertTrue(growth(cell, "root/p attach: root.") > 0, "attached again");
        assertTrue(growth(cell, "root/p detach: root.") > 0, "detached");
    }

    @Test
    void authorisationChangesBumpTheVersion() {
        PolicyEngine cell = cell(AuthMode.DENY);
        cell.run("boot.p2", """
                root at: "a" put: root/factory/domain create.
                root at: "b" put: root/factory/domain create.
                root at: "auth" put: (root/factory/authpolicy subject: root/a action: "print:" target: root focus: "t").
                """);
        assertTrue(growth(cell, "root/auth active: true.") > 0, "authorisation enabled");
        assertTrue(growth(cell, "root/auth reqneg.") > 0, "made negative");
        assertTrue(growth(cell, "root/auth reqcondition: [false].") > 0, "condition");
        assertTrue(growth(cell, "root/auth active: false.") > 0, "authorisation disabled");
        assertTrue(growth(cell, "root/a at: \"x\" put: root/b.") > 0, "domain membership, with authorisation on");
        long before = cell.policyVersion();
        cell.endBoot();
        assertTrue(cell.policyVersion() > before, "the end of boot changes the default decision");
    }

    @Test
    void withoutAuthorisationDomainMembershipLeavesTheVersionAlone() {
        PolicyEngine cell = cell(AuthMode.OFF);
        cell.run("boot.p2", "root at: \"a\" put: root/factory/domain create.");
        assertEquals(0, growth(cell, "root/a at: \"x\" put: root/factory/domain create."));
    }
}
