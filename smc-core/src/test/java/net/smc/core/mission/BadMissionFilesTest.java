package net.smc.core.mission;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.URISyntaxException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import net.smc.policy.api.PolicyRepository;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * One case per rule: each folder under {@code missions/bad/} holds {@code mission.instance.xml}
 * (with its own {@code mission.class.xml} when the class breaks the rule) and {@code expected.txt},
 * every error the loader must report, one per line, as {@code FILE:LINE:COL: <element>: message}
 * with FILE relative to the case folder. Lines starting with {@code #} say what the case shows.
 */
class BadMissionFilesTest {

    static Path resources() throws URISyntaxException {
        return Path.of(BadMissionFilesTest.class.getResource("/missions").toURI());
    }

    static Stream<String> cases() throws IOException, URISyntaxException {
        try (Stream<Path> dirs = Files.list(resources().resolve("bad"))) {
            return dirs.filter(Files::isDirectory).map(d -> d.getFileName().toString())
                    .filter(name -> !name.equals("common")).sorted().toList().stream();
        }
    }

    @Test
    void commonBase_fromWhichEveryCaseBreaksOneRule_isValid() throws Exception {
        MissionLoader loader = new MissionLoader(new PolicyRepository(resources().resolve("repo")));

        Mission mission = loader.load(resources().resolve("bad/common/base.instance.xml"));

        assertEquals(List.of("commander", "surveyor", "relay"), mission.roleNames());
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("cases")
    void badCase_reportsExactlyTheExpectedErrors(String name) throws Exception {
        Path dir = resources().resolve("bad").resolve(name);
        // Every case's class is the shared one in bad/common, beside the case's own folder.
        MissionLoader loader = new MissionLoader(new PolicyRepository(resources().resolve("repo")),
                List.of(resources().resolve("bad/common")));

        MissionException e = assertThrows(MissionException.class, () -> loader.load(dir.resolve("mission.instance.xml")));

        List<String> actual = e.errors().stream()
                .map(err -> dir.relativize(err.file()).toString().replace('\\', '/') + ":" + err.line() + ":"
                        + err.column() + ": " + (err.element() == null ? "" : "<" + err.element() + ">: ") + err.message())
                .toList();
        Path expectedFile = dir.resolve("expected.txt");
        assertTrue(Files.exists(expectedFile), () -> "no expected.txt; the loader reports:\n" + String.join("\n", actual));
        List<String> expected = Files.readAllLines(expectedFile).stream()
                .filter(line -> !line.isBlank() && !line.startsWith("#")).toList();
        assertEquals(String.join("\n", expected), String.join("\n", actual));
    }
}
