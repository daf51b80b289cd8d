package net.smc.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** {@code smc demo}: the rescue's and the reconnaissance's timelines, files and exit status, and the argument errors. */
class DemoCommandTest {
    private static final Path PROJECT = Path.of(System.getProperty("smc.project.dir", ".."));

    @Test
    void rescue_succeeds_printsTheSevenSteps_andWritesItsFiles(@TempDir Path out) throws Exception {
        // --gui in a headless test JVM: it says there is no display and runs headless.
        Smc.Result r = Smc.in(PROJECT).run("demo", "rescue", "--seed", "3", "--out", out.toString(), "--gui");
        assertEquals(0, r.status(), r.out() + r.err());
        for (String step : List.of("(i)", "(ii)", "(iii)", "(iv)", "(v)", "(vi)", "(vii)")) {
            assertTrue(r.out().contains(" " + step + " "), "step " + step + " on the timeline:\n" + r.out());
        }
        assertTrue(r.out().contains("display"), "says it runs headless:\n" + r.out());
        assertTrue(r.out().contains("succeeded: "), r.out());
        BufferedImage png = ImageIO.read(out.resolve("rescue.png").toFile());
        assertEquals(1200, png.getWidth());
        assertTrue(Files.size(out.resolve("rescue.gif")) > 10_000, "a film of some frames");
        List<String> csv = Files.readAllLines(out.resolve("rescue-timeline.csv"));
        assertEquals("time_ms,vehicle,what,detail,step", csv.get(0));
        assertTrue(csv.stream().anyMatch(l -> l.endsWith(",vii")), "the CSV has step (vii)");
    }

    @Test
    void anOutThatIsAFile_isAUsageErrorNamingIt(@TempDir Path dir) throws Exception {
        Path file = Files.writeString(dir.resolve("taken"), "not a folder");
        Smc.Result r = Smc.in(PROJECT).run("demo", "rescue", "--out", file.toString());
        assertEquals(2, r.status(), r.out() + r.err());
        assertTrue(r.err().contains("--out '" + file + "': not a directory (a file of that name is there)"), r.err());
        assertEquals("not a folder", Files.readString(file), "left as it was");
    }

    /** A folder the run could not write its files in is refused before the run, not after it. */
    @Test
    void anOutTheRunCannotWriteIn_isAUsageErrorBeforeTheRun() {
        // Linux's /proc/sys: a folder in which no file can be made, even by root
        org.junit.jupiter.api.Assumptions.assumeTrue(Files.isDirectory(Path.of("/proc/sys")), "a Linux /proc");
        Smc.Result r = Smc.in(PROJECT).run("demo", "rescue", "--out", "/proc/sys");
        assertEquals(2, r.status(), r.out() + r.err());
        assertTrue(r.err().contains("--out '/proc/sys': cannot write files in it: "), r.err());
        assertTrue(!r.out().contains("rescue of a wounded soldier"), "nothing is run:\n" + r.out());
        assertTrue(!r.err().contains("Exception"), r.err());
    }

    /** An output file whose name a folder holds ends the run with its name, not a stack trace. */
    @Test
    void anOutputFileThatIsAFolder_endsTheRunNamingIt(@TempDir Path out) throws Exception {
        Files.createDirectories(out.resolve("rescue.png"));
        Smc.Result r = Smc.in(PROJECT).run("demo", "--limit", "1", "--out", out.toString());
        assertEquals(1, r.status(), r.out() + r.err());
        assertTrue(r.err().contains("smc demo: cannot write the run's files in " + out + ": a folder of that name is there: "
                + out.resolve("rescue.png")), r.err());
        assertTrue(!r.err().contains("Exception"), r.err());
        assertTrue(Files.isDirectory(out.resolve("rescue.png")), "the folder is left as it was");
    }

    @Test
    void rescue_thatRunsOutOfTime_exitsOne_withTheReason(@TempDir Path out) {
        Smc.Result r = Smc.in(PROJECT).run("demo", "--limit", "5", "--out", out.toString());
        assertEquals(1, r.status(), r.out() + r.err());
        assertTrue(r.out().contains("failed: no assistance delivered within 5.0 s"), r.out());
        assertTrue(Files.exists(out.resolve("rescue.png")), "the picture of a failed run is written too");
    }

    /**
     * Over UDP on loopback at 2 mission seconds per wall second: the same steps, files and exit
     * status, and the datagrams went through the cells' sockets.
     */
    @Test
    void rescueOverUdp_succeeds_throughTheSockets(@TempDir Path out) throws Exception {
        Smc.Result r = Smc.in(PROJECT).run("demo", "rescue", "--transport", "udp", "--speed", "2", "--seed", "3",
                "--out", out.toString());
        assertEquals(0, r.status(), r.out() + r.err());
        for (String step : List.of("(i)", "(ii)", "(iii)", "(iv)", "(v)", "(vi)", "(vii)")) {
            assertTrue(r.out().contains(" " + step + " "), "step " + step + " on the timeline:\n" + r.out());
        }
        java.util.regex.Matcher m = java.util.regex.Pattern.compile("UDP: (\\d+) datagrams sent .*, (\\d+) delivered to cells")
                .matcher(r.out());
        assertTrue(m.find(), r.out());
        assertTrue(Long.parseLong(m.group(1)) > 50 && Long.parseLong(m.group(2)) > 50, r.out());
        assertTrue(r.out().contains("succeeded: "), r.out());
        assertEquals(1200, ImageIO.read(out.resolve("rescue.png").toFile()).getWidth());
        assertTrue(Files.size(out.resolve("rescue.gif")) > 10_000, "a film of some frames");
        assertTrue(Files.readAllLines(out.resolve("rescue-timeline.csv")).stream().anyMatch(l -> l.endsWith(",vii")));
    }

    @Test
    void rescueOverUdp_thatRunsOutOfTime_exitsOne_withTheReason(@TempDir Path out) {
        Smc.Result r = Smc.in(PROJECT).run("demo", "--transport", "udp", "--speed", "5", "--limit", "5", "--out", out.toString());
        assertEquals(1, r.status(), r.out() + r.err());
        assertTrue(r.out().contains("failed: no assistance delivered within 5.0 s"), r.out());
        assertTrue(Files.exists(out.resolve("rescue.png")), "the picture of a failed run is written too");
    }

    @Test
    void udpWithAWindow_isAUsageError(@TempDir Path out) {
        Smc.Result r = Smc.in(PROJECT).run("demo", "--transport", "udp", "--gui", "--out", out.toString());
        assertEquals(2, r.status(), r.out() + r.err());
        assertTrue(r.err().contains("--gui is for --transport sim only"), r.err());
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
        "burglary|unknown scenario 'burglary'",
        "--loss=1.5|--loss 1.5 is out of range",
        "--speed=0|--speed 0.0 must be a number of at least 0.01",
        "--transport=udp --speed=1e-300|--speed 1.0E-300 must be a number of at least 0.01",
        "--transport=carrier-pigeon|--transport 'carrier-pigeon' is unknown",
        "--limit=-1|--limit -1.0 must be at least 0.001 (1 ms)",
        "--limit=0.0001|--limit 1.0E-4 must be at least 0.001 (1 ms)",
        "reconnaissance --limit=0|--limit 0.0 must be at least 0.001 (1 ms)",
        "reconnaissance --limit=0.0001|--limit 1.0E-4 must be at least 0.001 (1 ms)",
        "reconnaissance --loss=-0.1|--loss -0.1 is out of range",
        "reconnaissance --transport=udp|--transport udp is available for the rescue only",
        "--seed=many|many",
    })
    void badArguments_exitTwo_withTheRule(String arguments, String message, @TempDir Path out) {
        List<String> args = new java.util.ArrayList<>(List.of("demo"));
        args.addAll(List.of(arguments.split(" ")));
        args.addAll(List.of("--out", out.toString()));
        Smc.Result r = Smc.in(PROJECT).run(args.toArray(String[]::new));
        assertEquals(2, r.status(), r.out() + r.err());
        assertTrue(r.err().contains(message), "expected '" + message + "' in:\n" + r.err());
        assertTrue(!Files.exists(out.resolve("rescue.png")), "nothing is run");
        assertTrue(!Files.exists(out.resolve("reconnaissance-map.png")), "nothing is run");
    }

    @Test
    void reconnaissance_thatRunsOutOfTime_exitsOne_withTheReason_andWritesItsFiles(@TempDir Path out) throws Exception {
        Smc.Result r = Smc.in(PROJECT).run("demo", "reconnaissance", "--seed", "2", "--limit", "30", "--out", out.toString());
        assertEquals(1, r.status(), r.out() + r.err());
        assertTrue(r.out().contains("failed: goal not met within 30.0 s of mission time: "), r.out());
        assertTrue(r.out().contains("CONFIGURATION") && r.out().contains("minimal: "), "the configurations on the timeline:\n" + r.out());
        assertTrue(r.out().matches("(?s).*configurations: forming -> minimal -> .*optimal.*"), r.out());
        BufferedImage png = ImageIO.read(out.resolve("reconnaissance-map.png").toFile());
        assertEquals(1200, png.getWidth());
        assertEquals(860, png.getHeight());
        assertTrue(Files.size(out.resolve("reconnaissance.gif")) > 5_000, "a film of some frames");
        List<String> csv = Files.readAllLines(out.resolve("reconnaissance-timeline.csv"));
        assertEquals("time_ms,vehicle,what,detail,step", csv.get(0));
        assertTrue(csv.stream().anyMatch(l -> l.contains(",ENTERED,")), "the robots' entrances are in the CSV");
    }
}
