package net.smc.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import net.smc.sim.experiment.CpuCosts;
import net.smc.sim.experiment.SetupTimeCsv;

class SetupTimeCommandTest {
    @TempDir
    Path dir;

    /** The project's policy repository, from the module's or the project's directory. */
    private static Path policies() {
        Path p = Path.of("..", "policies");
        return Files.isDirectory(p) ? p.toAbsolutePath() : Path.of("policies").toAbsolutePath();
    }

    private Path costs() throws Exception {
        Path file = dir.resolve("given-costs.properties");
        new CpuCosts(60_000, 120_000, 90_000, 800, 4, 600, 3, 3_000, 500, 20, 5).save(file);
        return file;
    }

    @Test
    void smallExperiment_writesOneCsvRowPerRun_andTheChart() throws Exception {
        Smc.Result r = Smc.in(dir).run("experiment", "setup-time", "--roles", "5,20", "--runs", "2", "--seed", "3",
                "--out", "out", "--costs", costs().toString(), "--policies", policies().toString());
        assertEquals(0, r.status(), r.err());
        List<String> csv = Files.readAllLines(dir.resolve("out/setup-time.csv"));
        assertEquals(SetupTimeCsv.HEADER, csv.get(0));
        assertEquals(1 + 2 * 2 * 2, csv.size(), String.join("\n", csv));
        for (String row : csv.subList(1, csv.size())) {
            String[] f = row.split(",", -1);
            assertEquals(9, f.length, row);
            assertTrue(!f[4].isEmpty(), "every role started: " + row);
            assertEquals(Integer.parseInt(f[0]) - 1, Integer.parseInt(f[8]), row);
        }
        assertTrue(Files.size(dir.resolve("out/setup-time.png")) > 1_000);
        assertTrue(Files.isRegularFile(dir.resolve("out/costs.properties")));
        assertTrue(r.err().contains("8/8 runs"), r.err());
        String shape = Files.readString(dir.resolve("out/shape.txt"));
        assertTrue(shape.startsWith("shape of the medians (sim):\n") && shape.contains("centralised / distributed"), shape);
        assertTrue(r.out().contains(shape), "the shape is printed too: " + r.out());
    }

    @Test
    void verbose_reportsEachRunsLevelsBusiestCellAndTrafficByKind() throws Exception {
        Smc.Result r = Smc.in(dir).run("experiment", "setup-time", "--roles", "5", "--runs", "1", "--seed", "3",
                "--schemes", "distributed", "--out", "out", "--costs", costs().toString(), "--policies",
                policies().toString(), "--verbose");
        assertEquals(0, r.status(), r.err());
        String out = r.out();
        assertTrue(out.contains("5 roles distributed run 1:"), out);
        assertTrue(out.contains("by level (first/half/90%/last): L1 ") && out.contains(" L3 ") && out.contains("slowest "), out);
        assertTrue(out.matches("(?s).*busiest cell (cdr|b\\d+l\\d+n\\d+): [0-9.]+ ms charged CPU:.*policy_load.*"), out);
        assertTrue(out.contains("team sent (datagrams/bytes):") && out.contains("ROLE_ASSIGNMENT"), out);
    }

    /** A costs file written before policy texts were compressed replays, the two costs it lacks defaulted and named. */
    @Test
    void aCostsFileWithoutTheCompressionCosts_replays_sayingWhichItDefaulted() throws Exception {
        Path old = dir.resolve("old-costs.properties");
        Files.writeString(old, Files.readString(costs()).lines()
                .filter(l -> !l.startsWith("deflateNanosPerByte") && !l.startsWith("inflateNanosPerByte"))
                .reduce("", (a, b) -> a + b + "\n"));
        Smc.Result r = Smc.in(dir).run("experiment", "setup-time", "--roles", "5", "--runs", "1", "--seed", "3",
                "--schemes", "distributed", "--out", "out", "--costs", old.toString(), "--policies",
                policies().toString());
        assertEquals(0, r.status(), r.err());
        assertTrue(r.out().contains("costs: " + old + " has no 'deflateNanosPerByte'"), r.out());
        assertTrue(r.out().contains("costs: " + old + " has no 'inflateNanosPerByte'"), r.out());
        assertEquals(CpuCosts.DEFAULT_DEFLATE_NANOS_PER_BYTE,
                CpuCosts.load(dir.resolve("out/costs.properties")).deflateNanosPerByte(), "saved with the run");
    }

    @Test
    void withoutVerbose_noRunReport() throws Exception {
        Smc.Result r = Smc.in(dir).run("experiment", "setup-time", "--roles", "5", "--runs", "1", "--seed", "3",
                "--schemes", "distributed", "--out", "out", "--costs", costs().toString(), "--policies",
                policies().toString());
        assertEquals(0, r.status(), r.err());
        assertTrue(!r.out().contains("busiest cell"), r.out());
    }

    @Test
    void runsOnSeveralThreads_writeTheSameRowsAsOneAtATime() throws Exception {
        Path given = costs();
        String[] common = {"experiment", "setup-time", "--roles", "5,20", "--runs", "4", "--seed", "11",
                "--costs", given.toString(), "--policies", policies().toString(), "--verbose"};
        Smc.Result one = Smc.in(dir).run(concat(common, "--jobs", "1", "--out", "one"));
        Smc.Result three = Smc.in(dir).run(concat(common, "--jobs", "3", "--out", "three"));
        assertEquals(0, one.status(), one.err());
        assertEquals(0, three.status(), three.err());
        List<String> rows = Files.readAllLines(dir.resolve("one/setup-time.csv"));
        assertEquals(1 + 2 * 2 * 4, rows.size(), String.join("\n", rows));
        assertEquals(rows, Files.readAllLines(dir.resolve("three/setup-time.csv")));
        // The reports come in run order, whole, whatever thread ran them.
        assertEquals(runReports(one.out()), runReports(three.out()));
        assertTrue(three.out().indexOf("20 roles centralised run 4:") > three.out().indexOf("20 roles centralised run 3:"),
                three.out());
    }

    /** The verbose reports of the runs, without the summary lines (wall times) and the output folder's name. */
    private static String runReports(String out) {
        return out.lines().filter(l -> !l.contains(" s wall)") && !l.startsWith("wrote "))
                .reduce("", (a, b) -> a + b + "\n");
    }

    private static String[] concat(String[] a, String... b) {
        String[] all = java.util.Arrays.copyOf(a, a.length + b.length);
        System.arraycopy(b, 0, all, a.length, b.length);
        return all;
    }

    /**
     * The radio options replace the model's figures: with hops of 50 ms, each of the three levels below
     * the commander waits at least one assignment's trip (two hops) and so at least 300 ms in all.
     */
    @Test
    void radioOptions_replaceTheModelsFigures_andSlowLinksSlowTheSetUp() throws Exception {
        Smc.Result r = Smc.in(dir).run("experiment", "setup-time", "--roles", "5", "--runs", "2", "--seed", "3",
                "--schemes", "distributed", "--out", "out", "--costs", costs().toString(), "--policies",
                policies().toString(), "--hops", "2", "--hop-latency", "50", "--hop-jitter", "0", "--bandwidth", "27.5",
                "--loss", "0");
        assertEquals(0, r.status(), r.err());
        assertTrue(r.out().contains("network: 2 hops x (50 ms + up to 0 ms), 27.50 Mbit/s per sender, 0.0% loss"), r.out());
        List<String> csv = Files.readAllLines(dir.resolve("out/setup-time.csv"));
        for (String row : csv.subList(1, csv.size())) {
            assertTrue(Double.parseDouble(row.split(",", -1)[4]) >= 300, "three levels of 100 ms trips: " + row);
        }
        Smc.Result model = Smc.in(dir).run("experiment", "setup-time", "--roles", "5", "--runs", "1", "--seed", "3",
                "--schemes", "distributed", "--out", "model", "--costs", costs().toString(), "--policies",
                policies().toString());
        assertTrue(model.out().contains("network: 2 hops x (2 ms + up to 2 ms), 2.75 Mbit/s per sender, 1.0% loss"),
                model.out());
        List<String> fast = Files.readAllLines(dir.resolve("model/setup-time.csv"));
        assertTrue(Double.parseDouble(fast.get(1).split(",", -1)[4]) < 300, "the model's radio: " + fast.get(1));
    }

    /**
     * On a radio that loses most datagrams the cells give up on critical messages: the point's line
     * counts them, and the communication manager's warning for each is quieted (unless asked for).
     */
    @Test
    void criticalMessagesGivenUpOn_areCountedOnThePointsLine() throws Exception {
        Smc.Result r = Smc.in(dir).run("experiment", "setup-time", "--roles", "5", "--runs", "2", "--seed", "3",
                "--schemes", "distributed", "--out", "out", "--costs", costs().toString(), "--policies",
                policies().toString(), "--loss", "0.8", "--limit", "5000");
        assertEquals(0, r.status(), r.err());
        java.util.regex.Matcher m = java.util.regex.Pattern.compile("incomplete, (\\d+) critical messages given up on, ")
                .matcher(r.out());
        assertTrue(m.find() && Long.parseLong(m.group(1)) > 0, r.out());
        assertEquals("error", System.getProperty(SetupTimeCommand.COMM_LOG_LEVEL));

        Smc.Result clean = Smc.in(dir).run("experiment", "setup-time", "--roles", "5", "--runs", "1", "--seed", "3",
                "--schemes", "distributed", "--out", "clean", "--costs", costs().toString(), "--policies",
                policies().toString(), "--loss", "0");
        assertTrue(!clean.out().contains("given up on"), "none given up on, none said: " + clean.out());
    }

    /**
     * {@code --network lan}: the switched LAN's figures (one hop of at most 1 ms, 100 Mbit/s, no loss),
     * so every run of the same seeds sets up faster than on the ad-hoc radio, whose shortest one-way
     * trip alone is 4 ms and a level at least two of them; an option replaces one of its figures.
     */
    @Test
    void lanNetwork_usesTheSwitchedLansFigures_andSetsUpFasterThanTheRadio() throws Exception {
        String[] common = {"experiment", "setup-time", "--roles", "10", "--runs", "3", "--seed", "3", "--schemes",
            "distributed", "--costs", costs().toString(), "--policies", policies().toString()};
        Smc.Result lan = Smc.in(dir).run(concat(common, "--out", "lan", "--network", "LAN"));
        assertEquals(0, lan.status(), lan.err());
        assertTrue(lan.out().contains("network: 1 hop x (0 ms + up to 1 ms), 100.00 Mbit/s per sender, 0.0% loss"),
                lan.out());
        Smc.Result radio = Smc.in(dir).run(concat(common, "--out", "radio", "--network", "adhoc"));
        assertEquals(0, radio.status(), radio.err());
        List<String> fast = Files.readAllLines(dir.resolve("lan/setup-time.csv"));
        List<String> slow = Files.readAllLines(dir.resolve("radio/setup-time.csv"));
        assertEquals(4, fast.size(), String.join("\n", fast));
        for (int i = 1; i < fast.size(); i++) {
            double lanMs = Double.parseDouble(fast.get(i).split(",", -1)[4]);
            double radioMs = Double.parseDouble(slow.get(i).split(",", -1)[4]);
            assertTrue(lanMs < radioMs, "run " + i + ": lan " + lanMs + " ms against the radio's " + radioMs);
        }
        Smc.Result lossy = Smc.in(dir).run(concat(common, "--out", "lossy", "--network", "lan", "--hops", "3", "--loss",
                "0.02"));
        assertEquals(0, lossy.status(), lossy.err());
        assertTrue(lossy.out().contains("network: 3 hops x (0 ms + up to 1 ms), 100.00 Mbit/s per sender, 2.0% loss"),
                lossy.out());
    }

    /** The help formats every description: a bare '%' in one made picocli warn on stderr and print it raw. */
    @Test
    void help_describesTheNetworkModels_withoutAFormatWarning() {
        java.io.PrintStream before = System.err;
        java.io.ByteArrayOutputStream caught = new java.io.ByteArrayOutputStream();
        System.setErr(new java.io.PrintStream(caught, true));
        Smc.Result r;
        try {
            r = Smc.in(dir).run("experiment", "setup-time", "--help");
        } finally {
            System.setErr(before);
        }
        assertEquals(0, r.status(), r.err());
        assertTrue(r.out().contains("1% loss"), r.out());
        assertTrue(!caught.toString().contains("picocli WARN"), caught.toString());
    }

    @Test
    void unknownNetwork_isAUsageErrorNamingTheModels() {
        Smc.Result r = Smc.in(dir).run("experiment", "setup-time", "--network", "wifi", "--out", "o");
        assertEquals(2, r.status());
        assertTrue(r.err().contains("--network 'wifi': it must be 'adhoc' or 'lan'"), r.err());
        assertTrue(!Files.exists(dir.resolve("o")), "refused before anything was written");
    }

    @Test
    void radioValuesOutOfRange_areUsageErrorsNamingTheOption() {
        String[][] cases = {
            {"--loss", "1", "--loss 1.0: it must be from 0 to below 1"},
            {"--loss", "-0.5", "--loss -0.5: it must be from 0 to below 1"},
            {"--hops", "0", "--hops 0: it must be from 1 to 100"},
            {"--hops", "101", "--hops 101: it must be from 1 to 100"},
            {"--hop-latency", "-1", "--hop-latency -1: it must be from 0 to 60000 ms"},
            {"--hop-latency", "9223372036854775807", "--hop-latency 9223372036854775807: it must be from 0 to 60000 ms"},
            {"--hop-jitter", "-3", "--hop-jitter -3: it must be from 0 to 60000 ms"},
            {"--bandwidth", "0", "--bandwidth 0.0: it must be from 0.00001 to 1000000 Mbit/s"},
            {"--bandwidth", "NaN", "--bandwidth NaN: it must be from 0.00001 to 1000000 Mbit/s"},
        };
        for (String[] c : cases) {
            Smc.Result r = Smc.in(dir).run("experiment", "setup-time", c[0], c[1], "--out", "o");
            assertEquals(2, r.status(), c[0] + " " + c[1]);
            assertTrue(r.err().contains(c[2]), r.err());
        }
        assertTrue(!Files.exists(dir.resolve("o")), "refused before anything was written");
    }

    /** Spare vehicles: the team is larger, the seats are the same, every one of them started. */
    @Test
    void spareVehicles_fillTheSameSeats_andTheTeamLineSaysSo() throws Exception {
        Smc.Result r = Smc.in(dir).run("experiment", "setup-time", "--roles", "20", "--runs", "2", "--seed", "3",
                "--out", "out", "--costs", costs().toString(), "--policies", policies().toString(), "--spare", "50");
        assertEquals(0, r.status(), r.err());
        assertTrue(r.out().contains("team: one vehicle per seat and 50% more of each role, rounded up"), r.out());
        List<String> csv = Files.readAllLines(dir.resolve("out/setup-time.csv"));
        assertEquals(1 + 2 * 2, csv.size(), String.join("\n", csv));
        for (String row : csv.subList(1, csv.size())) {
            String[] f = row.split(",", -1);
            assertTrue(!f[4].isEmpty(), "every role started: " + row);
            assertEquals(19, Integer.parseInt(f[8]), row);
        }
    }

    @Test
    void spareOutOfRange_orOverUdp_isAUsageError() {
        Smc.Result negative = Smc.in(dir).run("experiment", "setup-time", "--spare", "-1", "--out", "o");
        assertEquals(2, negative.status());
        assertTrue(negative.err().contains("--spare -1: it must be from 0 to 1000"), negative.err());
        Smc.Result udp = Smc.in(dir).run("experiment", "setup-time", "--spare", "10", "--transport", "udp", "--roles", "5",
                "--out", "o");
        assertEquals(2, udp.status());
        assertTrue(udp.err().contains("--spare 10 with --transport udp"), udp.err());
    }

    @Test
    void zeroJobs_isAUsageError() {
        Smc.Result r = Smc.in(dir).run("experiment", "setup-time", "--jobs", "0", "--out", "o");
        assertEquals(2, r.status());
        assertTrue(r.err().contains("--jobs 0: it must be 1 or more"), r.err());
    }

    @Test
    void unknownScheme_isAUsageError() {
        Smc.Result r = Smc.in(dir).run("experiment", "setup-time", "--schemes", "anarchic", "--out", "o");
        assertEquals(2, r.status());
        assertTrue(r.err().contains("unknown scheme 'anarchic'"), r.err());
    }

    @Test
    void bothSchemes_byThatWord_orNamedTwice_runEachSchemeOnce() throws Exception {
        Smc.Result r = Smc.in(dir).run("experiment", "setup-time", "--roles", "5", "--runs", "1", "--seed", "3",
                "--schemes", "both,distributed,centralized", "--out", "out", "--costs", costs().toString(),
                "--policies", policies().toString());
        assertEquals(0, r.status(), r.err());
        List<String> rows = Files.readAllLines(dir.resolve("out/setup-time.csv"));
        assertEquals(List.of("distributed", "centralised"), rows.subList(1, rows.size()).stream()
                .map(row -> row.split(",")[1]).toList(), String.join("\n", rows));
    }

    @Test
    void anOutThatIsAFile_isAUsageErrorNamingIt() throws Exception {
        Files.writeString(dir.resolve("taken"), "not a folder");
        Smc.Result r = Smc.in(dir).run("experiment", "setup-time", "--roles", "5", "--runs", "1", "--out", "taken",
                "--costs", costs().toString(), "--policies", policies().toString());
        assertEquals(2, r.status(), r.err());
        assertTrue(r.err().contains("--out 'taken': not a directory (a file of that name is there)"), r.err());
        assertEquals("not a folder", Files.readString(dir.resolve("taken")), "left as it was");
    }

    @Test
    void aCostsFileThatIsNotThere_isAUsageErrorSayingSo() {
        Smc.Result r = Smc.in(dir).run("experiment", "setup-time", "--roles", "5", "--runs", "1", "--out", "o",
                "--costs", "missing.properties", "--policies", policies().toString());
        assertEquals(2, r.status(), r.err());
        assertTrue(r.err().contains("--costs missing.properties: no such file"), r.err());
    }

    /** Depth 2: the commander manages 199 role types, and its role-mission outgrows what a policy reply carries. */
    @Test
    void aShapeWhoseMissionCannotLoad_isAUsageErrorNamingIt_beforeAnyRun() throws Exception {
        Smc.Result r = Smc.in(dir).run("experiment", "setup-time", "--roles", "5,200", "--depth", "2", "--runs", "1",
                "--out", "out", "--costs", costs().toString(), "--policies", policies().toString());
        assertEquals(2, r.status(), r.err());
        assertTrue(r.err().contains("--roles 200 (depth 2, fan-out 199): the generated distributed mission does not load: "
                + "policy 'policy:/roles/commander/distributed' is ") && r.err().contains("a policy file must be at most 65000"),
                r.err());
        assertTrue(!r.out().contains("5 roles distributed"), "no point ran: " + r.out());
    }

    @Test
    void tooFewRolesForTheDepth_isAUsageError() {
        Smc.Result r = Smc.in(dir).run("experiment", "setup-time", "--roles", "3", "--out", "o",
                "--policies", policies().toString());
        assertEquals(2, r.status());
        assertTrue(r.err().contains("--roles 3") && r.err().contains("depth 4"), r.err());
    }

    @Test
    void zeroRuns_isAUsageError() {
        Smc.Result r = Smc.in(dir).run("experiment", "setup-time", "--runs", "0", "--out", "o");
        assertEquals(2, r.status());
        assertTrue(r.err().contains("--runs 0"), r.err());
    }

    @Test
    void udpTransport_withMoreThanFiftyRoles_isAUsageError() {
        Smc.Result r = Smc.in(dir).run("experiment", "setup-time", "--transport", "udp", "--roles", "5,100", "--out", "o");
        assertEquals(2, r.status());
        assertTrue(r.err().contains("--roles 100 with --transport udp") && r.err().contains("at most 50 roles"), r.err());
    }

    @Test
    void unknownTransport_isAUsageError() {
        Smc.Result r = Smc.in(dir).run("experiment", "setup-time", "--transport", "carrier-pigeon", "--out", "o");
        assertEquals(2, r.status());
        assertTrue(r.err().contains("--transport carrier-pigeon: it must be sim, udp or sim,udp"), r.err());
    }

    /** Both transports: one CSV with a transport column, the udp rows from real runs on loopback. */
    @Test
    void simAndUdp_fiveRoles_bothSchemes_writeRowsOfEachTransport() throws Exception {
        Smc.Result r = Smc.in(dir).run("experiment", "setup-time", "--roles", "5", "--runs", "1", "--transport", "sim,udp",
                "--out", "out", "--costs", costs().toString(), "--policies", policies().toString(), "--limit", "60000");
        assertEquals(0, r.status(), r.err());
        List<String> csv = Files.readAllLines(dir.resolve("out/setup-time.csv"));
        assertEquals(1 + 2 * 2, csv.size(), String.join("\n", csv));
        int udp = 0;
        for (String row : csv.subList(1, csv.size())) {
            String[] f = row.split(",", -1);
            assertTrue(!f[4].isEmpty() && Double.parseDouble(f[4]) > 0, "every role started: " + row);
            assertEquals(4, Integer.parseInt(f[8]), row);
            assertTrue(Long.parseLong(f[5]) > 0 && Long.parseLong(f[6]) > 0, "messages counted: " + row);
            if (f[2].equals("udp")) {
                udp++;
            }
        }
        assertEquals(2, udp, String.join("\n", csv));
        assertTrue(r.out().contains("udp  median"), r.out());
        assertTrue(Files.size(dir.resolve("out/setup-time.png")) > 1_000);
    }

    /** Warm-up runs over UDP run before the recorded ones and are not recorded. */
    @Test
    void udpWarmup_runsBeforeTheRecordedRuns_andIsNotRecorded() throws Exception {
        Smc.Result r = Smc.in(dir).run("experiment", "setup-time", "--roles", "5", "--runs", "1", "--transport", "udp",
                "--schemes", "centralised", "--warmup", "2", "--out", "out", "--policies", policies().toString(),
                "--limit", "60000");
        assertEquals(0, r.status(), r.err());
        assertTrue(r.out().contains("warm-up: 2 unrecorded runs of each point over UDP before its recorded runs"), r.out());
        assertTrue(r.err().contains("5 roles, warm-up 1/2") && r.err().contains("5 roles, warm-up 2/2"), r.err());
        List<String> csv = Files.readAllLines(dir.resolve("out/setup-time.csv"));
        assertEquals(2, csv.size(), String.join("\n", csv));
        assertTrue(csv.get(1).startsWith("5,centralised,udp,1,"), csv.get(1));
    }

    @Test
    void warmupOutOfRange_orWithoutUdp_isAUsageError() {
        Smc.Result negative = Smc.in(dir).run("experiment", "setup-time", "--warmup", "-1", "--transport", "udp",
                "--roles", "5", "--out", "o");
        assertEquals(2, negative.status());
        assertTrue(negative.err().contains("--warmup -1: it must be from 0 to 1000"), negative.err());
        Smc.Result sim = Smc.in(dir).run("experiment", "setup-time", "--warmup", "3", "--out", "o");
        assertEquals(2, sim.status());
        assertTrue(sim.err().contains("--warmup 3 without --transport udp"), sim.err());
        assertTrue(!Files.exists(dir.resolve("o")), "refused before anything was written");
    }

    @Test
    void noExperiment_isAUsageError() {
        Smc.Result r = Smc.in(dir).run("experiment");
        assertEquals(2, r.status());
        assertTrue(r.err().contains("no experiment given"), r.err());
    }
}
