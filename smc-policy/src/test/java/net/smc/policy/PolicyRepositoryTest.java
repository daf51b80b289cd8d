package net.smc.policy;

import net.smc.policy.api.PolicyRepository;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class PolicyRepositoryTest {
    @TempDir
    Path dir;

    private PolicyRepository repositoryWith(String relative, String text) throws IOException {
        Path file = dir.resolve(relative);
        Files.createDirectories(file.getParent());
        Files.writeString(file, text);
        return new PolicyRepository(dir);
    }

    @Test
    void uri_namesTheP2FileUnderTheFolder() throws IOException {
        PolicyRepository repo = repositoryWith("roles/surveyor/assign.p2", "root print: 1.");
        assertEquals(dir.resolve("roles/surveyor/assign.p2").toAbsolutePath().normalize(),
                repo.pathOf("policy:/roles/surveyor/assign"));
        assertEquals(Optional.of("root print: 1."), repo.read("policy:/roles/surveyor/assign"));
    }

    @Test
    void list_givesEveryUriSorted() throws IOException {
        repositoryWith("b/two.p2", "1");
        PolicyRepository repo = repositoryWith("a/one.p2", "1");
        Files.writeString(dir.resolve("a/notes.txt"), "not a policy");
        assertEquals(List.of("policy:/a/one", "policy:/b/two"), repo.list());
    }

    @Test
    void missingFile_readsAsEmpty() {
        assertEquals(Optional.empty(), new PolicyRepository(dir).read("policy:/no/such"));
    }

    @Test
    void uriWithDotDot_isRefusedNamingTheSegment() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new PolicyRepository(dir).pathOf("policy:/roles/../../etc/passwd"));
        assertEquals("invalid policy URI 'policy:/roles/../../etc/passwd': segment '..' must be letters, digits, _ or -",
                e.getMessage());
    }

    @Test
    void uriWithoutScheme_isRefused() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new PolicyRepository(dir).pathOf("roles/x"));
        assertTrue(e.getMessage().startsWith("invalid policy URI 'roles/x'"), e.getMessage());
    }

    @Test
    void emptySegment_isRefused() {
        assertThrows(IllegalArgumentException.class, () -> new PolicyRepository(dir).pathOf("policy://x"));
        assertThrows(IllegalArgumentException.class, () -> new PolicyRepository(dir).pathOf("policy:/"));
    }

    @Test
    void find_staysInsideTheFolder() throws IOException {
        PolicyRepository repo = repositoryWith("lib/common.p2", "1");
        assertTrue(repo.find("lib/common.p2").isPresent());
        assertTrue(repo.find("../outside.p2").isEmpty());
    }

    @Test
    void cellLoad_runsTheFileAndReportsItsErrorsUnderTheUri() throws IOException {
        PolicyRepository repo = repositoryWith("demo/broken.p2", "root print: 1.\nroot frob.");
        List<String> lines = new ArrayList<>();
        List<String> errors = new ArrayList<>();
        PolicyEngine cell = PolicyEngine.builder().output(lines::add).errors(d -> errors.add(d.toString())).repository(repo).build();

        RunResult result = cell.load("policy:/demo/broken");

        assertEquals(RunResult.Status.RUNTIME_ERROR, result.status());
        assertEquals(List.of("1"), lines);
        assertEquals(List.of("policy:/demo/broken:2:6: unknown operation 'frob' on SelfManagedCell"), errors);
    }

    /** A policy of the repository includes and reads the repository's files only, not one beside it or anywhere. */
    @Test
    void cellLoad_ofAPolicyNamingAFileOutsideTheRepository_isRefused(@TempDir Path elsewhere) throws IOException {
        Path secret = Files.writeString(elsewhere.resolve("secret.p2"), "root print: \"secret\".");
        repositoryWith("roles/helper.p2", "root print: \"helper\".");
        PolicyRepository repo = repositoryWith("roles/a.p2", "include \"helper.p2\".\ninclude \"" + secret + "\".");
        repositoryWith("roles/b.p2", "root print: (root read: \"" + secret + "\").");
        List<String> lines = new ArrayList<>();
        List<String> errors = new ArrayList<>();
        PolicyEngine cell = PolicyEngine.builder().output(lines::add).errors(d -> errors.add(d.toString())).repository(repo).build();

        cell.load("policy:/roles/a");
        cell.load("policy:/roles/b");

        assertEquals(List.of(), lines, "nothing of the file outside was run");
        String refused = ": cannot read '" + secret + "': it is outside the policy repository; a policy of the repository"
                + " includes and reads files of the repository only";
        assertEquals(List.of("policy:/roles/a:2:9" + refused, "load:1:6: cannot run 'policy:/roles/a': 1 syntax error",
                "policy:/roles/b:1:19" + refused), errors);
    }

    @Test
    void cellLoad_ofAMissingUri_saysFileNotFound() {
        List<String> errors = new ArrayList<>();
        PolicyEngine cell = PolicyEngine.builder().errors(d -> errors.add(d.toString())).repository(new PolicyRepository(dir)).build();
        cell.load("policy:/no/such");
        assertEquals(List.of("load:1:6: cannot read 'policy:/no/such': file not found"), errors);
    }

    @Test
    void cellLoad_withoutRepository_saysSo() {
        List<String> errors = new ArrayList<>();
        PolicyEngine cell = PolicyEngine.builder().errors(d -> errors.add(d.toString())).build();
        cell.load("policy:/x");
        assertEquals(List.of("load:1:6: cannot read 'policy:/x': no policy repository is configured"), errors);
    }
}
