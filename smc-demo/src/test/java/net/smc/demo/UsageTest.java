package net.smc.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Help, version and usage errors (exit status 2, a message naming the problem, a usage hint). */
class UsageTest {
    @TempDir
    Path dir;

    private Smc smc;

    @BeforeEach
    void setUp() {
        smc = Smc.in(dir);
    }

    @Test
    void help_listsTheCommands() {
        Smc.Result result = smc.run("--help");

        assertEquals(0, result.status());
        assertTrue(result.out().startsWith("Usage: smc [-hV] COMMAND"), result.out());
        assertTrue(result.out().contains("run ") && result.out().contains("shell "), result.out());
        assertEquals("", result.err());
    }

    @Test
    void runHelp_explainsExitStatuses_includingPolicyErrors() {
        Smc.Result result = smc.run("run", "--help");

        assertEquals(0, result.status());
        assertTrue(result.out().startsWith("Usage: smc run "), result.out());
        assertTrue(result.out().contains("inside a policy"), result.out());
        assertTrue(result.out().contains("--auth=allow|deny"), result.out());
    }

    @Test
    void shellHelp_explainsHowInputsEnd() {
        Smc.Result result = smc.run("shell", "--help");

        assertEquals(0, result.status());
        assertTrue(result.out().startsWith("Usage: smc shell "), result.out());
        assertTrue(result.out().contains("An input ends at a line whose last non-blank character is '.'"), result.out());
    }

    @Test
    void version_printsTheVersion() {
        Smc.Result result = smc.run("--version");

        assertEquals(List.of("smc " + Main.VERSION), result.outLines());
        assertEquals(0, result.status());
    }

    @Test
    void missingFile_isAUsageErrorNamingTheFile() {
        String later = smc.file("later.p2", "root print: 1.\n");

        Smc.Result result = smc.run("run", later, "missing.p2");

        assertEquals(2, result.status());
        assertEquals("", result.out(), "nothing runs after a usage error");
        assertEquals("smc run: cannot read 'missing.p2': no such file", result.errLines().get(0));
        assertTrue(result.err().contains("Try 'smc run --help'"), result.err());
    }

    @Test
    void directoryAsFile_isAUsageError() throws Exception {
        Files.createDirectory(dir.resolve("folder.p2"));

        Smc.Result result = smc.run("run", "folder.p2");

        assertEquals(2, result.status());
        assertEquals("smc run: cannot read 'folder.p2': is a directory", result.errLines().get(0));
    }

    @Test
    void missingBootFileOfTheShell_isAUsageError() {
        Smc.Result result = smc.withInput("root print: 1.\n", "shell", "missing.p2");

        assertEquals(2, result.status());
        assertEquals("", result.out());
        assertEquals("smc shell: cannot read 'missing.p2': no such file", result.errLines().get(0));
    }

    @Test
    void badAuthValue_isAUsageError() {
        String file = smc.file("a.p2", "root print: 1.\n");

        Smc.Result result = smc.run("run", "--auth", "maybe", file);

        assertEquals(2, result.status());
        assertEquals("", result.out());
        assertEquals("smc run: Invalid value for option '--auth': 'maybe' is neither 'allow' nor 'deny'", result.errLines().get(0));
        assertTrue(result.err().contains("Usage: smc run "), result.err());
    }

    @Test
    void noFiles_isAUsageError() {
        Smc.Result result = smc.run("run");

        assertEquals(2, result.status());
        assertTrue(result.errLines().get(0).startsWith("smc run: Missing required parameter: 'FILE.p2'"), result.err());
    }

    @Test
    void unknownOption_isAUsageError() {
        Smc.Result result = smc.run("run", "--frob", "a.p2");

        assertEquals(2, result.status());
        assertEquals("smc run: Unknown option: '--frob'", result.errLines().get(0));
    }

    @Test
    void missingRepository_isAUsageError() {
        String file = smc.file("a.p2", "root print: 1.\n");

        Smc.Result result = smc.run("run", "--repository", "nowhere", file);

        assertEquals(2, result.status());
        assertEquals("smc run: --repository 'nowhere': no such directory", result.errLines().get(0));
    }

    @Test
    void unknownCommand_isAUsageError() {
        Smc.Result result = smc.run("frob");

        assertEquals(2, result.status());
        assertEquals("smc: unknown command 'frob'", result.errLines().get(0));
        assertTrue(result.err().contains("Try 'smc --help'"), result.err());
    }

    @Test
    void noCommand_isAUsageError() {
        Smc.Result result = smc.run();

        assertEquals(2, result.status());
        assertEquals("smc: no command given: use run, shell, validate, keys, node, status, demo or experiment", result.errLines().get(0));
    }
}
