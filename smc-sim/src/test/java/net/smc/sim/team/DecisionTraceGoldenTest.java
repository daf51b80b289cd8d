package net.smc.sim.team;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.LongStream;
import java.util.stream.Stream;

import net.smc.core.cell.Missions;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestFactory;

/**
 * Pins the team protocols' decisions: each seeded fault run ({@link FaultSchedule}) of a fixed set
 * of seeds must record exactly the trace it recorded when the golden file was made (every cell
 * event and fault, with its virtual time, vehicle, kind and detail). The golden holds per seed the
 * scheme, the number of events and the trace's SHA-256, and for a few seeds the whole trace, so that
 * a difference can be read line by line.
 *
 * <p>Regenerate (only when a change of decisions is intended) with
 * {@code ./gradlew :smc-core:junit -Ptests='.*DecisionTraceGoldenTest' -Ptest.smc.golden.update=true}.
 */
class DecisionTraceGoldenTest {
    private static final long SEEDS = 50;
    private static final long FAULT_MILLIS = 20_000;
    /** Seeds whose whole trace is kept beside the digests. */
    private static final Set<Long> FULL = Set.of(1L, 2L, 3L, 4L);
    private static final String RESOURCE = "net/smc/sim/team/decision-traces/";
    private static final boolean UPDATE = Boolean.getBoolean("smc.golden.update");

    /** One seed's run: its scheme, and its trace (one line per event). */
    private record Run(long seed, String scheme, List<String> lines) {
        String digest() {
            try {
                MessageDigest sha = MessageDigest.getInstance("SHA-256");
                for (String line : lines) {
                    sha.update(line.getBytes(StandardCharsets.UTF_8));
                    sha.update((byte) '\n');
                }
                return HexFormat.of().formatHex(sha.digest());
            } catch (NoSuchAlgorithmException e) {
                throw new IllegalStateException(e);
            }
        }

        String summary() {
            return seed + " " + scheme + " " + lines.size() + " " + digest();
        }
    }

    private static Run run(long seed) {
        List<String> lines = new ArrayList<>();
        FaultSchedule.Outcome outcome = new FaultSchedule(Missions.reconnaissance(), Missions.centralised(),
                Missions.REPOSITORY, seed, FAULT_MILLIS).events(e -> lines.add(e.toString())).run();
        return new Run(seed, outcome.scheme().name(), lines);
    }

    @TestFactory
    Stream<DynamicTest> eachSeedReplaysItsGoldenTrace() throws IOException {
        if (UPDATE) {
            return Stream.of(DynamicTest.dynamicTest("update the golden traces", DecisionTraceGoldenTest::update));
        }
        Map<Long, String> golden = summaries();
        return LongStream.rangeClosed(1, SEEDS).mapToObj(seed -> DynamicTest.dynamicTest("seed " + seed, () -> {
            String expected = golden.get(seed);
            if (expected == null) {
                fail("no golden trace for seed " + seed + "; regenerate with -Ptest.smc.golden.update=true");
            }
            Run run = run(seed);
            if (FULL.contains(seed)) {
                assertSameLines(seed, read(RESOURCE + "seed-" + seed + ".txt").lines().toList(), run.lines());
            }
            assertEquals(expected, run.summary(), "seed " + seed + ": trace differs from the golden (seed scheme events sha256)");
        }));
    }

    /** The golden covers both schemes and runs with crashes and partitions. */
    @Test
    void goldenCoversBothSchemesAndCrashesAndPartitions() throws IOException {
        Map<Long, String> golden = summaries();
        assertEquals(SEEDS, golden.size(), "one golden line per seed");
        assertTrue(golden.values().stream().anyMatch(s -> s.contains(" CENTRALISED ")), "a centralised seed");
        assertTrue(golden.values().stream().anyMatch(s -> s.contains(" DISTRIBUTED ")), "a distributed seed");
        String full = String.join("\n", FULL.stream().sorted().map(seed -> {
            try {
                return read(RESOURCE + "seed-" + seed + ".txt");
            } catch (IOException e) {
                throw new IllegalStateException(e);
            }
        }).toList());
        assertTrue(full.contains("*** crash "), "a kept trace with a crash");
        assertTrue(full.contains("*** partition "), "a kept trace with a partition");
    }

    private static void assertSameLines(long seed, List<String> expected, List<String> actual) {
        int n = Math.min(expected.size(), actual.size());
        for (int i = 0; i < n; i++) {
            if (!expected.get(i).equals(actual.get(i))) {
                fail("seed " + seed + ", event " + (i + 1) + ":\n  golden: " + expected.get(i) + "\n  now:    " + actual.get(i));
            }
        }
        assertEquals(expected.size(), actual.size(), "seed " + seed + ": number of events");
    }

    private static Map<Long, String> summaries() throws IOException {
        Map<Long, String> out = new LinkedHashMap<>();
        for (String line : read(RESOURCE + "summary.txt").lines().toList()) {
            if (!line.isBlank() && !line.startsWith("#")) {
                out.put(Long.parseLong(line.substring(0, line.indexOf(' '))), line);
            }
        }
        return out;
    }

    private static String read(String resource) throws IOException {
        try (InputStream in = DecisionTraceGoldenTest.class.getClassLoader().getResourceAsStream(resource)) {
            if (in == null) {
                throw new IOException("missing golden resource " + resource + "; regenerate with -Ptest.smc.golden.update=true");
            }
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
    }

    private static void update() throws IOException {
        Path dir = Path.of(System.getProperty("smc.project.dir", "../"))
                .resolve("smc-sim/src/test/resources").resolve(RESOURCE);
        Files.createDirectories(dir);
        StringBuilder summary = new StringBuilder("# seed scheme events sha256 (DecisionTraceGoldenTest; faults for "
                + FAULT_MILLIS + " ms)\n");
        for (long seed = 1; seed <= SEEDS; seed++) {
            Run run = run(seed);
            summary.append(run.summary()).append('\n');
            if (FULL.contains(seed)) {
                Files.writeString(dir.resolve("seed-" + seed + ".txt"), String.join("\n", run.lines()) + "\n");
            }
        }
        Files.writeString(dir.resolve("summary.txt"), summary.toString());
    }
}
