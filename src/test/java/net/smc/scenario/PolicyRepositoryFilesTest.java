package net.smc.scenario;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import net.smc.core.role.Loaded;
import net.smc.core.role.Role;
import net.smc.policy.RunResult;
import net.smc.policy.lang.Parser;
import net.smc.policy.lang.Unit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/** Every file of the policy repository parses, and every role's files load through the Role-Manager. */
class PolicyRepositoryFilesTest {
    private static final List<String> MISSION_ROLES = List.of("aggregator", "commander", "hdetector", "relay", "surveyor");

    static Stream<String> uris() {
        return PaperCell.REPOSITORY.list().stream();
    }

    /** The roles that have a role-mission file, policies/roles/<role>/mission.p2. */
    static Stream<String> roles() throws IOException {
        try (Stream<Path> dirs = Files.list(PaperCell.REPOSITORY.root().resolve("roles"))) {
            return dirs.filter(d -> Files.isRegularFile(d.resolve("mission.p2")))
                    .map(d -> d.getFileName().toString()).sorted().toList().stream();
        }
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("uris")
    void everyRepositoryFile_parses(String uri) throws Exception {
        String text = PaperCell.REPOSITORY.read(uri).orElseThrow();

        Unit unit = Parser.parse(uri, text);

        assertEquals(List.of(), unit.errors(), uri);
    }

    @Test
    void everyRoleOfTheTwoMissions_hasARoleMission() throws IOException {
        assertEquals(MISSION_ROLES, roles().toList());
        assertTrue(PaperCell.REPOSITORY.read("policy:/roles/commander/assign").isPresent());
        assertTrue(PaperCell.REPOSITORY.read("policy:/roles/commander/reassign").isPresent());
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("roles")
    void roleMissionAndAuthorisations_loadWithoutErrors(String name) throws Exception {
        PaperCell c = new PaperCell();

        Loaded loaded = c.roles.load(PaperCell.role(name));

        assertTrue(c.errors.isEmpty(), c.errors::toString);
        assertTrue(!loaded.policies().isEmpty(), () -> name + " mission creates no obligation policy");
        assertTrue(!loaded.authorisations().isEmpty(), () -> name + " auth creates no authorisation policy");
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("roles")
    void roleWithdrawn_leavesNothingBehind(String name) throws Exception {
        PaperCell c = new PaperCell();
        String before = Trees.describe(c.cell.root());
        c.roles.load(PaperCell.role(name));

        c.roles.withdraw(name);

        assertEquals(before, Trees.describe(c.cell.root()));
    }

    @Test
    void allFiveRoles_loadTogetherInOneCell() throws Exception {
        PaperCell c = new PaperCell();

        for (String name : MISSION_ROLES) {
            c.roles.load(PaperCell.role(name));
        }
        c.roles.load(Role.builder("commander").mission("policy:/roles/commander/assign", "policy:/roles/commander/reassign")
                .build());

        assertTrue(c.errors.isEmpty(), c.errors::toString);
        assertEquals(MISSION_ROLES.size(), c.roles.loadedRoles().size());
    }

    @Test
    void bootEvents_runTwice_keepTheirTemplates() throws Exception {
        PaperCell c = new PaperCell();
        Object template = c.cell.resolve("/event/newUAV");

        RunResult again = c.cell.load("policy:/boot/events");

        assertTrue(again.ok() && again.diagnostics().isEmpty(), again.diagnostics()::toString);
        assertEquals(template, c.cell.resolve("/event/newUAV"));
    }
}
