package net.smc.core.role;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import net.smc.policy.api.PolicyRepository;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** A load that fails leaves the cell exactly as it was, and says which part failed and why. */
class RoleManagerAtomicityTest {
    private final Fixture f = new Fixture();
    private final Explorer explorer = new Explorer();

    private static PolicySource text(String name, String text) {
        return PolicySource.text(name, text);
    }

    /** Loads a role that must fail; checks the tree is unchanged and nothing of it fires. */
    private RoleLoadException failing(Role role) {
        String before = Fixture.tree(f.cell.root());
        RoleLoadException e = assertThrows(RoleLoadException.class, () -> f.roles.load(role));
        assertEquals(before, Fixture.tree(f.cell.root()), "the domain tree changed");
        f.out.clear();
        f.go(1);
        assertEquals(List.of(), f.out, "a policy of the failed load still fires");
        assertFalse(f.roles.isLoaded(role.name()));
        return e;
    }

    @Test
    void runtimeErrorInOnePolicy_amongGoodOnes_leavesTheCellAsItWas() throws Exception {
        Role role = Role.builder("surveyor")
                .mission(Fixture.printer("surveyor", "good1"))
                .mission(text("broken", """
                        p := root/factory/ecapolicy create.
                        root/role/surveyor/policy at: "half" put: p.
                        root/nothing frob.
                        """))
                .mission(Fixture.printer("surveyor", "good2"))
                .task("Explorer", () -> explorer)
                .build();

        RoleLoadException e = failing(role);

        assertEquals("policy 'broken'", e.part());
        assertTrue(e.getMessage().contains("role 'surveyor' was not loaded"), e.getMessage());
        assertTrue(e.getMessage().contains("broken:3:1: path not found 'root/nothing'"), e.getMessage());
        assertFalse(explorer.isRunning());
    }

    @Test
    void syntaxError_namesThePolicyAndThePosition() throws Exception {
        RoleLoadException e = failing(Role.builder("surveyor")
                .mission(Fixture.printer("surveyor", "good"))
                .mission(text("broken", "p := root/factory/ecapolicy create.\np event: ."))
                .build());

        assertEquals("policy 'broken'", e.part());
        assertTrue(e.reasons().get(0).startsWith("broken:2:"), e.reasons()::toString);
    }

    @Test
    void missingUri_namesTheUri(@TempDir Path repo) throws Exception {
        Fixture withRepo = new Fixture(new PolicyRepository(repo), "");
        Role role = Role.builder("surveyor").mission("policy:/roles/nowhere/mission").build();
        String before = Fixture.tree(withRepo.cell.root());

        RoleLoadException e = assertThrows(RoleLoadException.class, () -> withRepo.roles.load(role));

        assertEquals(before, Fixture.tree(withRepo.cell.root()));
        assertEquals("policy 'policy:/roles/nowhere/mission'", e.part());
        assertTrue(e.getMessage().contains("cannot read 'policy:/roles/nowhere/mission': file not found"), e.getMessage());
    }

    @Test
    void errorReportedByAPolicyWhileTheFileRuns_failsTheLoad() throws Exception {
        Fixture failingBoot = new Fixture(null, """
                bad := root/factory/ecapolicy create.
                bad event: root/event/go; action: [:n | root/missing frob].
                bad active: true.
                """);
        Role role = Role.builder("surveyor").mission(text("raiser", "root/event/go create: #(1).")).build();
        String before = Fixture.tree(failingBoot.cell.root());

        RoleLoadException e = assertThrows(RoleLoadException.class, () -> failingBoot.roles.load(role));

        assertEquals(before, Fixture.tree(failingBoot.cell.root()));
        assertTrue(e.getMessage().contains("unhandled action error: path not found 'root/missing'"), e.getMessage());
    }

    @Test
    void policyActivatedButNotStored_isCaught_andRetired() throws Exception {
        RoleLoadException e = failing(Role.builder("surveyor").mission(text("stray", """
                p := root/factory/ecapolicy create.
                p event: root/event/go; action: [:n | root print: "stray"].
                p active: true.
                """)).build());

        assertTrue(e.getMessage().contains("created an obligation policy that it did not store under root/role/surveyor/policy"),
                e.getMessage());
    }

    @Test
    void authorisationStoredAmongObligationPolicies_breaksTheConvention() throws Exception {
        RoleLoadException e = failing(Role.builder("surveyor").mission(text("misplaced", """
                a := root/factory/authpolicy subject: root/role/surveyor/policy action: "*" target: root/event focus: "st".
                root/role/surveyor/policy at: "a" put: a.
                """)).build());

        assertTrue(e.getMessage().contains("root/role/surveyor/policy/a is a AuthorisationPolicy;"
                + " root/role/surveyor/policy holds only obligation policies"), e.getMessage());
    }

    @Test
    void fileReplacingAnExistingEntry_breaksTheConvention() throws Exception {
        RoleLoadException e = failing(Role.builder("surveyor").mission(Fixture.printer("surveyor", "good"))
                .mission(text("replacer", "root/event at: \"go\" put: (root/factory/event create: #(\"n\")).")).build());

        assertEquals("policy 'replacer'", e.part());
        assertTrue(e.getMessage().contains("it replaced root/event/go; a role's files may add entries but must not"
                + " replace or remove existing ones"), e.getMessage());
    }

    @Test
    void taskThatCannotBeMade_namesTheTask() throws Exception {
        RoleLoadException e = failing(Role.builder("surveyor").mission(Fixture.printer("surveyor", "good"))
                .task("Explorer", () -> {
                    throw new IllegalStateException("no camera");
                }).build());

        assertEquals("task 'Explorer'", e.part());
        assertTrue(e.getMessage().contains("it could not be made: no camera"), e.getMessage());
    }

    @Test
    void taskThatFailsToStart_stopsTheTasksStartedBeforeIt() throws Exception {
        Explorer broken = new Explorer() {
            @Override
            protected void onStart() {
                throw new IllegalStateException("motor fault");
            }
        };
        RoleLoadException e = failing(Role.builder("surveyor").mission(Fixture.printer("surveyor", "good"))
                .task("Explorer", () -> explorer).task("Broken", () -> broken).build());

        assertEquals("task 'Broken'", e.part());
        assertTrue(e.getMessage().contains("motor fault"), e.getMessage());
        assertEquals(1, explorer.starts);
        assertEquals(1, explorer.stops);
    }

    @Test
    void localInterfaceNamingAnOperationTheTaskLacks_failsTheLoad() throws Exception {
        RoleLoadException e = failing(Role.builder("surveyor").task("Explorer", () -> explorer)
                .local(new LocalInterface(List.of(new TaskOperation("Explorer", "fly:")), List.of())).build());

        assertEquals("the local interface", e.part());
        assertTrue(e.getMessage().contains("task 'Explorer' (Explorer) has no operation 'fly:'"), e.getMessage());
    }

    @Test
    void failedExtension_leavesTheLoadedRoleWorking() throws Exception {
        f.roles.load(Role.builder("surveyor").mission(Fixture.printer("surveyor", "a")).build());

        failingExtension();

        f.out.clear();
        f.go(2);
        assertEquals(List.of("a 2"), f.out);
        assertTrue(f.roles.isLoaded("surveyor"));
    }

    private void failingExtension() throws Exception {
        String before = Fixture.tree(f.cell.root());
        Role extended = Role.builder("surveyor").mission(Fixture.printer("surveyor", "a"))
                .mission(Fixture.printer("surveyor", "b")).mission(text("broken", "root/nothing frob.")).build();
        assertThrows(RoleLoadException.class, () -> f.roles.load(extended));
        assertEquals(before, Fixture.tree(f.cell.root()));
    }

    @Test
    void failedFirstLoad_removesTheRoleDomainItMade() throws Exception {
        failing(Role.builder("surveyor").mission(text("broken", "root/nothing frob.")).build());

        assertFalse(f.cell.root().entries().containsKey(RoleManager.ROLE_DOMAIN));
    }
}
