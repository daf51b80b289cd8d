package net.smc.core.role;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import net.smc.policy.runtime.AuthorisationPolicy;
import net.smc.policy.runtime.ObligationPolicy;
import org.junit.jupiter.api.Test;

class RoleManagerWithdrawTest {
    /** A role with a bit of everything: policies, an authorisation, a task, role state, an outside entry. */
    private static final PolicySource EVERYTHING = PolicySource.text("everything", """
            p := root/factory/ecapolicy create.
            p event: root/event/go; action: [:n | root/role/surveyor/task/Explorer goTo: n. root print: "went " + n].
            root/role/surveyor/policy at: "steer" put: p.
            root/role/surveyor at: "log" put: #().
            root/event at: "surveyed" put: (root/factory/event create: #("area")).
            """);
    private static final PolicySource MAY_STEER = PolicySource.text("maySteer", """
            a := root/factory/authpolicy subject: root/role/surveyor/policy action: "goTo:"
                    target: root/role/surveyor/task focus: "st".
            root/role/surveyor/auth at: "maySteer" put: a.
            """);

    private final Fixture f = new Fixture();
    private final Explorer explorer = new Explorer();
    private final Role surveyor = Role.builder("surveyor").mission(EVERYTHING).authorisation(MAY_STEER)
            .task("Explorer", () -> explorer)
            .local(new LocalInterface(List.of(new TaskOperation("Explorer", "goTo:")), List.of()))
            .external(new ExternalInterface(List.of(new TaskOperation("Explorer", "goTo:")), List.of(), List.of(), List.of()))
            .build();

    @Test
    void withdraw_leavesTheDomainTreeAsBeforeTheLoad() throws Exception {
        String before = Fixture.tree(f.cell.root());
        f.roles.load(surveyor);
        // A call from another role leaves its subject under root/role/surveyor/peers (and is denied).
        assertThrows(ExternalCallException.class,
                () -> new ExternalGateway(f.roles).invoke(new Caller("c7", "commander"), "surveyor", "policies"));

        f.roles.withdraw("surveyor");

        assertEquals(before, Fixture.tree(f.cell.root()));
        assertFalse(f.roles.isLoaded("surveyor"));
    }

    @Test
    void withdraw_deactivatesThePolicies_soTheyNoLongerFire() throws Exception {
        f.roles.load(surveyor);
        ObligationPolicy steer = (ObligationPolicy) f.cell.resolve("root/role/surveyor/policy/steer");
        AuthorisationPolicy maySteer = (AuthorisationPolicy) f.cell.resolve("root/role/surveyor/auth/maySteer");

        f.roles.withdraw("surveyor");
        f.go(5);

        assertFalse(steer.isActive());
        assertFalse(maySteer.active());
        assertEquals(List.of(), f.out);
        assertEquals(List.of(), explorer.visited);
    }

    @Test
    void withdraw_stopsTheTasks() throws Exception {
        f.roles.load(surveyor);

        f.roles.withdraw("surveyor");

        assertFalse(explorer.isRunning());
        assertEquals(1, explorer.stops);
    }

    @Test
    void withdraw_keepsARoleDomainItDidNotMake() throws Exception {
        f.run("root at: \"role\" put: root/factory/domain create.");
        f.roles.load(surveyor);

        f.roles.withdraw("surveyor");

        assertTrue(f.cell.root().entries().containsKey("role"));
    }

    @Test
    void withdraw_leavesOtherRolesWorking() throws Exception {
        f.roles.load(surveyor);
        f.roles.load(Role.builder("relay").mission(Fixture.printer("relay", "r")).build());

        f.roles.withdraw("surveyor");
        f.go(1);

        assertEquals(List.of("r 1"), f.out);
    }

    @Test
    void withdrawnRole_canBeLoadedAgain() throws Exception {
        f.roles.load(surveyor);
        f.roles.withdraw("surveyor");

        f.roles.load(surveyor);
        f.go(2);

        assertEquals(List.of("went 2"), f.out);
        assertEquals(2, explorer.starts);
    }

    @Test
    void withdrawingARoleNotLoaded_namesIt() throws Exception {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> f.roles.withdraw("relay"));

        assertEquals("role 'relay' is not loaded on this cell (loaded: [])", e.getMessage());
    }

    @Test
    void taskFailingToStop_isReportedAfterTheWithdrawalCompletes() throws Exception {
        Explorer stubborn = new Explorer() {
            @Override
            protected void onStop() {
                throw new IllegalStateException("brakes stuck");
            }
        };
        String before = Fixture.tree(f.cell.root());
        f.roles.load(Role.builder("surveyor").mission(Fixture.printer("surveyor", "a")).task("Stubborn", () -> stubborn).build());

        IllegalStateException e = assertThrows(IllegalStateException.class, () -> f.roles.withdraw("surveyor"));

        assertTrue(e.getMessage().startsWith("role 'surveyor' was withdrawn, but task 'Stubborn' failed to stop"), e.getMessage());
        assertEquals(before, Fixture.tree(f.cell.root()));
    }
}
