package net.smc.core.role;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import net.smc.policy.RunResult;
import net.smc.policy.runtime.ObligationPolicy;
import org.junit.jupiter.api.Test;

/** The role object root/role/<name>: management operations and reassign:scheme:, as PonderTalk sees them. */
class RoleObjectTest {
    private final Fixture f = new Fixture();

    private void loadCommander() throws Exception {
        f.roles.load(Role.builder("commander").manages("surveyor", "aggregator")
                .mission(Fixture.printer("commander", "a")).task("Explorer", Explorer::new).build());
    }

    private String failure(String text) {
        RunResult result = f.cell.run("test", text);
        assertFalse(result.ok());
        return result.diagnostics().toString();
    }

    @Test
    void reassign_ofAManagedRole_goesToTheReassignmentService() throws Exception {
        loadCommander();

        f.run("root/role/commander reassign: \"surveyor\" scheme: \"default\".");

        assertEquals(List.of("commander reassigns surveyor by default"), f.reassigned);
    }

    @Test
    void reassign_ofARoleNotManaged_isAnErrorNamingBoth() throws Exception {
        loadCommander();

        String error = failure("root/role/commander reassign: \"relay\" scheme: \"default\".");

        assertTrue(error.contains("role 'commander' does not manage role 'relay', so it cannot re-assign it"
                + " (it manages [aggregator, surveyor])"), error);
        assertEquals(List.of(), f.reassigned);
    }

    @Test
    void reassign_withoutAReassignmentService_isAnError() throws Exception {
        RoleManager bare = RoleManager.builder(f.cell).build();
        bare.load(Role.builder("commander").manages("surveyor").build());

        String error = failure("root/role/commander reassign: \"surveyor\" scheme: \"default\".");

        assertTrue(error.contains("this cell has no re-assignment service"), error);
    }

    @Test
    void managementOperations_describeTheRole() throws Exception {
        loadCommander();

        assertEquals("commander", f.run("root/role/commander name"));
        assertEquals("[aggregator, surveyor]", net.smc.policy.PolicyEngine.print(f.run("root/role/commander manages")));
        assertEquals("[a]", net.smc.policy.PolicyEngine.print(f.run("root/role/commander policies")));
        assertEquals("[Explorer]", net.smc.policy.PolicyEngine.print(f.run("root/role/commander tasks")));
        assertEquals("<Role root/role/commander>", net.smc.policy.PolicyEngine.print(f.run("root/role/commander")));
    }

    @Test
    void disable_andEnable_switchARolePolicy() throws Exception {
        loadCommander();
        ObligationPolicy a = (ObligationPolicy) f.cell.resolve("root/role/commander/policy/a");

        f.run("root/role/commander disable: \"a\".");
        assertFalse(a.isActive());
        assertEquals(Boolean.FALSE, f.run("root/role/commander isEnabled: \"a\""));
        f.run("root/role/commander enable: \"a\".");
        assertTrue(a.isActive());
    }

    @Test
    void disable_ofAnUnknownPolicy_namesWhatTheRoleHas() throws Exception {
        loadCommander();

        String error = failure("root/role/commander disable: \"nope\".");

        assertTrue(error.contains("role 'commander' has no policy 'nope' (it has [a])"), error);
    }
}
