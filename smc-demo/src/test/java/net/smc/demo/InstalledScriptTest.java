package net.smc.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Runs the script {@code ./gradlew :smc-demo:installDist} installs (the smc-demo test task
 * depends on it). A missing script fails the test: it means the install did not run.
 */
class InstalledScriptTest {
    @TempDir
    Path dir;

    /** The installed script: under the project folder the build passes in, else under the current one. */
    private static Path script() {
        String projectDir = System.getProperty("smc.project.dir");
        Path demo = projectDir != null ? Path.of(projectDir, "smc-demo") : Path.of("").toAbsolutePath();
        return demo.resolve("build/install/smc/bin/smc");
    }

    @Test
    void installedSmcRun_printsToStdout_andExitsWithTheStatus() throws Exception {
        Path script = script();
        assertTrue(Files.isExecutable(script), "the installed smc script is missing at " + script
                + "; run ./gradlew :smc-demo:installDist first");
        Path file = Files.writeString(dir.resolve("a.p2"), "root print: 3 + 4.\nroot print: \"a\" + \"b\".\nroot exit: 3.\n");

        Process process = new ProcessBuilder(script.toString(), "run", file.toString())
                .redirectError(ProcessBuilder.Redirect.DISCARD)
                .start();
        process.getOutputStream().close();
        String out = new String(process.getInputStream().readAllBytes(), StandardCharsets.UTF_8);

        assertTrue(process.waitFor(60, TimeUnit.SECONDS), "smc did not end within 60 s");
        assertEquals("7\nab\n", out);
        assertEquals(3, process.exitValue());
    }
}
