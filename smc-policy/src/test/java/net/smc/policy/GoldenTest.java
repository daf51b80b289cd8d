package net.smc.policy;

import net.smc.policy.api.PolicyRepository;
import net.smc.policy.api.Limits;
import net.smc.policy.api.AuthMode;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.stream.Stream;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.TestFactory;

/**
 * Runs every golden case: {@code golden/<feature>/<case>.p2} beside {@code <case>.out}. The format
 * and the directives are described in {@code golden/README.md}.
 */
class GoldenTest {
    static final long FIXED_CLOCK = 1767225600000L;

    static Path goldenDir() {
        String configured = System.getProperty("smc.golden.dir");
        return Path.of(configured != null ? configured : "src/test/resources/golden");
    }

    @TestFactory
    Stream<DynamicTest> goldenCases() throws IOException {
        Path root = goldenDir();
        List<Path> cases;
        try (Stream<Path> files = Files.walk(root)) {
            cases = files.filter(p -> p.toString().endsWith(".p2"))
                    .filter(p -> !root.relativize(p).startsWith("_repository"))
                    .filter(p -> Files.exists(expectedFile(p)))
                    .sorted()
                    .toList();
        }
        assertTrue(cases.size() >= 200, "expected at least 200 golden cases, found " + cases.size());
        return cases.stream().map(p -> DynamicTest.dynamicTest(root.relativize(p).toString(), () -> check(p)));
    }

    private static Path expectedFile(Path script) {
        String name = script.getFileName().toString();
        return script.resolveSibling(name.substring(0, name.length() - 3) + ".out");
    }

    private static void check(Path script) throws IOException {
        String expected = Files.readString(expectedFile(script));
        String actual = String.join("\n", run(script));
        assertEquals(strip(expected), actual, "output of " + script.getFileName());
    }

    private static String strip(String s) {
        return s.endsWith("\n") ? s.substring(0, s.length() - 1) : s;
    }

    /** Runs a golden script as the README describes; answers its output and error lines in order. */
    static List<String> run(Path script) throws IOException {
        String text = Files.readString(script);
        AuthMode auth = AuthMode.OFF;
        Limits limits = Limits.DEFAULT;
        for (String line : text.split("\n", -1)) {
            if (!line.startsWith("//")) {
                break;
            }
            String directive = line.substring(2).trim();
            if (directive.startsWith("auth:")) {
                auth = AuthMode.valueOf(directive.substring(5).trim().toUpperCase());
            } else if (directive.startsWith("steps:")) {
                limits = limits.withMaxSteps(Long.parseLong(directive.substring(6).trim()));
            }
        }
        List<String> lines = new ArrayList<>();
        long[] now = {FIXED_CLOCK};
        PolicyEngine cell = PolicyEngine.builder()
                .output(lines::add)
                .errors(d -> lines.add(d.toString()))
                .auth(auth)
                .limits(limits)
                .clock(() -> now[0])
                .arguments(List.of("-a", "-b", "gold", "-c", "silver", "copper", "-d"))
                .random(new Random(42))
                .repository(new PolicyRepository(goldenDir().resolve("_repository")))
                .build();
        String name = script.getFileName().toString();
        List<String> units = units(text);
        List<Long> advances = advances(text);
        for (int i = 0; i < units.size(); i++) {
            if (i == 1) {
                cell.endBoot();
            }
            if (i > 0) {
                advance(cell, now, advances.get(i - 1));
            }
            if (cell.exitStatus().isPresent()
                    || cell.run(name, units.get(i), script).status() == RunResult.Status.EXITED) {
                break;
            }
        }
        return lines;
    }

    /** Moves the virtual clock on by {@code millis}, running each timer task at its due time. */
    static void advance(PolicyEngine cell, long[] now, long millis) {
        long target = now[0] + millis;
        while (cell.timers().nextDue().isPresent() && cell.timers().nextDue().getAsLong() <= target
                && cell.exitStatus().isEmpty()) {
            now[0] = Math.max(now[0], cell.timers().nextDue().getAsLong());
            cell.timers().runDue();
        }
        now[0] = target;
    }

    private static boolean isSplit(String line) {
        return line.equals("//-- unit") || line.startsWith("//-- advance ");
    }

    /** For each split line in order: the milliseconds of {@code //-- advance N}, 0 for {@code //-- unit}. */
    static List<Long> advances(String text) {
        List<Long> advances = new ArrayList<>();
        for (String line : text.split("\n", -1)) {
            if (isSplit(line)) {
                advances.add(line.startsWith("//-- advance ") ? Long.parseLong(line.substring(13).trim()) : 0L);
            }
        }
        return advances;
    }

    /** Splits at lines that are exactly {@code //-- unit}; each unit keeps its lines' numbers. */
    static List<String> units(String text) {
        List<String> units = new ArrayList<>();
        String[] lines = text.split("\n", -1);
        StringBuilder current = new StringBuilder();
        for (int i = 0; i < lines.length; i++) {
            if (isSplit(lines[i])) {
                units.add(current.toString());
                current = new StringBuilder("\n".repeat(i + 1));
                continue;
            }
            current.append(lines[i]);
            if (i < lines.length - 1) {
                current.append('\n');
            }
        }
        units.add(current.toString());
        return units;
    }
}
