package net.smc.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.DatagramSocket;
import java.net.InetSocketAddress;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Runs the script {@code ./gradlew :smc-demo:installDist} installs (the smc-demo test task
 * depends on it): {@code smc run}'s output and exit status, and {@code smc node} ending cleanly on
 * SIGTERM. A missing script fails the test: it means the install did not run.
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

    @Test
    void installedSmcNode_onSigterm_closesCleanlyAndSaysSo() throws Exception {
        Path script = script();
        assertTrue(Files.isExecutable(script), "the installed smc script is missing at " + script);
        Smc smc = Smc.in(dir);
        assertEquals(0, smc.run("keys", "authority", "--out", "keys").status());
        assertEquals(0, smc.run("keys", "vehicle", "--id", "cdr", "--out", "keys").status());
        assertEquals(0, smc.run("keys", "issue", "--authority", "keys/authority.key", "--vehicle-pub", "keys/cdr.pub", "--id",
                "cdr", "--mission", "HouseSurvey", "--valid-for", "1h", "--out", "keys/cdr.cred").status());
        Path mission = Path.of(System.getProperty("smc.project.dir", "..")).resolve("missions/reconnaissance.instance.xml");
        Path log = dir.resolve("node.log");

        Process process = new ProcessBuilder(script.toString(), "node", "--mission", mission.toString(),
                "--credential", "keys/cdr.cred", "--key", "keys/cdr.key", "--authority", "keys/authority.pub",
                "--bind", "127.0.0.1:" + freePort(), "--broadcast", "127.255.255.255:" + freePort(), "--commander",
                "--resources", "communication")
                .directory(dir.toFile()).redirectErrorStream(true).redirectOutput(log.toFile()).start();
        process.getOutputStream().close();
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
        while (!Files.readString(log).contains(" COMMANDING ")) {
            assertTrue(process.isAlive() && System.nanoTime() < deadline, "the node did not come up: " + Files.readString(log));
            Thread.sleep(20);
        }
        process.destroy();   // SIGTERM

        assertTrue(process.waitFor(30, TimeUnit.SECONDS), "smc node did not end within 30 s of SIGTERM");
        List<String> lines = Files.readAllLines(log);
        assertTrue(lines.get(0).startsWith("up: vehicle cdr of mission HouseSurvey at 127.0.0.1:"), lines.toString());
        assertEquals("down: vehicle cdr stopped: the process was asked to end (SIGTERM or SIGINT)",
                lines.get(lines.size() - 1), lines.toString());
        assertEquals(143, process.exitValue(), "the JVM's status for SIGTERM");
    }

    @Test
    void installedSmcRun_aFileOf8MB_runsUnderAHeapOf48MB() throws Exception {
        Path script = script();
        assertTrue(Files.isExecutable(script), "the installed smc script is missing at " + script);
        Path file = dir.resolve("big.p2");
        int repeats = 200_000;   // 42 bytes each: 8.4 MB, 1.4 million tokens
        try (var out = Files.newBufferedWriter(file)) {
            out.write("x := 0.\n");
            for (int i = 0; i < repeats; i++) {
                out.write("x := x + 1.\ns := \"a string literal " + (1_000_000 + i) + "\".\n");
            }
            out.write("root print: x. root print: s.\n");
        }
        ProcessBuilder builder = new ProcessBuilder(script.toString(), "run", file.toString())
                .redirectErrorStream(true);
        builder.environment().put("JAVA_OPTS", "-Xmx48m");   // the file's text alone is 8.4 MB of it

        Process process = builder.start();
        process.getOutputStream().close();
        String out = new String(process.getInputStream().readAllBytes(), StandardCharsets.UTF_8);

        assertTrue(process.waitFor(120, TimeUnit.SECONDS), "smc did not end within 120 s");
        assertEquals(repeats + "\na string literal " + (1_000_000 + repeats - 1) + "\n", out);
        assertEquals(0, process.exitValue());
    }

    @Test
    void installedSmcRun_onSigterm_endsAnEndlessLoopAndSaysSo() throws Exception {
        Path script = script();
        assertTrue(Files.isExecutable(script), "the installed smc script is missing at " + script);
        Path file = Files.writeString(dir.resolve("loop.p2"), "root print: \"looping\".\n[true] whileTrue: [1 + 1].\n");
        Path err = dir.resolve("err.log");
        Process process = new ProcessBuilder(script.toString(), "run", file.toString())
                .redirectError(err.toFile()).start();
        process.getOutputStream().close();
        var out = new java.io.BufferedReader(new java.io.InputStreamReader(process.getInputStream(), StandardCharsets.UTF_8));
        assertEquals("looping", out.readLine(), "the loop starts after this line");

        process.destroy();   // SIGTERM

        assertTrue(process.waitFor(30, TimeUnit.SECONDS), "smc run did not end within 30 s of SIGTERM");
        assertEquals(List.of("smc run: stopped: the process was asked to end (SIGTERM or SIGINT)"), Files.readAllLines(err));
        assertEquals(143, process.exitValue(), "the JVM's status for SIGTERM");
    }

    private static int freePort() throws IOException {
        try (DatagramSocket probe = new DatagramSocket(new InetSocketAddress("0.0.0.0", 0))) {
            return probe.getLocalPort();
        }
    }
}
