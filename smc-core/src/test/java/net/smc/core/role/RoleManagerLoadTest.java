package net.smc.core.role;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import net.smc.policy.runtime.AuthorisationPolicy;
import net.smc.policy.api.DomainHandle;
import net.smc.policy.api.Handle;
import net.smc.policy.runtime.ObligationPolicy;
import org.junit.jupiter.api.Test;

class RoleManagerLoadTest {
    private static final PolicySource STEER = PolicySource.text("steer", """
            p := root/factory/ecapolicy create.
            p event: root/event/go; action: [:n | root/role/surveyor/task/Explorer goTo: n].
            root/role/surveyor/policy at: "steer" put: p.
            """);
    private static final PolicySource MAY_STEER = PolicySource.text("maySteer", """
            a := root/factory/authpolicy subject: root/role/surveyor/policy action: "goTo:"
                    target: root/role/surveyor/task focus: "st".
            root/role/surveyor/auth at: "maySteer" put: a.
            """);

    private final Fixture f = new Fixture();
    private final Explorer explorer = new Explorer();

    private Role surveyor() {
        return Role.builder("surveyor").mission(STEER).authorisation(MAY_STEER).task("Explorer", () -> explorer).build();
    }

    @Test
    void load_putsPoliciesAuthorisationsAndTasksUnderTheRoleDomain() throws Exception {
        f.roles.load(surveyor());

        assertInstanceOf(ObligationPolicy.class, f.cell.resolve("root/role/surveyor/policy/steer"));
        assertInstanceOf(AuthorisationPolicy.class, f.cell.resolve("root/role/surveyor/auth/maySteer"));
        assertSame(explorer, ((Handle) f.cell.resolve("root/role/surveyor/task/Explorer")).impl());
        assertInstanceOf(DomainHandle.class, f.cell.resolve("root/role/surveyor/peers"));
    }

    @Test
    void load_reportsWhatItAdded() throws Exception {
        Loaded loaded = f.roles.load(surveyor());

        assertEquals(new Loaded("surveyor", List.of("steer", "maySteer"), List.of("steer"), List.of("maySteer"),
                List.of("Explorer")), loaded);
        assertFalse(loaded.alreadyPresent());
    }

    @Test
    void load_enablesThePoliciesAndStartsTheTasks() throws Exception {
        f.roles.load(surveyor());

        assertTrue(((ObligationPolicy) f.cell.resolve("root/role/surveyor/policy/steer")).isActive());
        assertTrue(((AuthorisationPolicy) f.cell.resolve("root/role/surveyor/auth/maySteer")).active());
        assertTrue(explorer.isRunning());
        assertEquals(1, explorer.starts);
    }

    @Test
    void loadedRole_actsUnderItsOwnAuthorisations() throws Exception {
        f.roles.load(surveyor());

        f.go(7);

        assertEquals(List.of(java.math.BigDecimal.valueOf(7)), explorer.visited);
        assertTrue(f.errors.isEmpty(), f.errors::toString);
    }

    @Test
    void loadedRole_withoutItsAuthorisation_isDeniedByDefault() throws Exception {
        f.roles.load(Role.builder("surveyor").mission(STEER).task("Explorer", () -> explorer).build());

        f.go(7);

        assertTrue(explorer.visited.isEmpty());
        assertEquals(1, f.errors.size());
        assertTrue(f.errors.get(0).message().contains("Ponder2AuthorizationException: goTo:"), f.errors::toString);
    }

    @Test
    void load_makesTheRoleDomainOnce_forSeveralRoles() throws Exception {
        f.roles.load(Role.builder("surveyor").mission(Fixture.printer("surveyor", "s")).build());
        f.roles.load(Role.builder("relay").mission(Fixture.printer("relay", "r")).build());

        assertEquals(List.of("surveyor", "relay"), List.copyOf(((DomainHandle) f.cell.resolve("root/role")).entries().keySet()));
        f.go(1);
        assertEquals(List.of("s 1", "r 1"), f.out);
        assertEquals(List.of("surveyor", "relay"), List.copyOf(f.roles.loadedRoles()));
    }

    @Test
    void load_runsPolicyFilesInOrder_missionBeforeAuthorisations() throws Exception {
        f.roles.load(Role.builder("surveyor")
                .authorisation(PolicySource.text("auth", "root print: \"auth\"."))
                .mission(PolicySource.text("mission", "root print: \"mission\"."))
                .build());

        assertEquals(List.of("mission", "auth"), f.out);
    }

    @Test
    void roleDescription_isAvailableWhileLoaded() throws Exception {
        Role role = surveyor();
        f.roles.load(role);

        assertEquals(role, f.roles.role("surveyor").orElseThrow());
        assertTrue(f.roles.isLoaded("surveyor"));
        assertFalse(f.roles.isLoaded("relay"));
    }
}
