package net.smc.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class ValidateCommandTest {
    private static final Path PROJECT = Path.of(System.getProperty("smc.project.dir", "..")).toAbsolutePath();
    private static final String REPOSITORY = PROJECT.resolve("policies").toString();

    @TempDir
    Path dir;

    private Smc smc;

    @BeforeEach
    void setUp() {
        smc = Smc.in(dir);
    }

    private String writeRescueCopy(String instanceText) throws Exception {
        Files.copy(PROJECT.resolve("missions/rescue.class.xml"), dir.resolve("rescue.class.xml"));
        return smc.file("rescue.instance.xml", instanceText);
    }

    @Test
    void validInstance_printsTheResolvedMission_andExitStatusIs0() {
        Smc.Result result = smc.run("validate", "--repository", REPOSITORY,
                PROJECT.resolve("missions/reconnaissance.instance.xml").toString());

        assertEquals("", result.err());
        assertEquals(0, result.status());
        assertEquals(List.of(
                "mission HouseSurvey (class Reconnaissance)",
                "parameters:",
                "  comTimeout = 500 (int)",
                "  failureTimeout = 3000 (int)",
                "  scheme = distributed (string)",
                "  backups = 1 (int)",
                "roles (minimal..optimal):",
                "  commander   1..1  needs resources [communication]",
                "    policy policy:/roles/commander/assign",
                "    policy policy:/roles/commander/reassign",
                "    policy policy:/roles/commander/mission",
                "    authorisation policy:/roles/commander/auth",
                "  surveyor    2..2  needs resources [motion, video] and tasks [Explorer]",
                "    policy policy:/roles/surveyor/mission",
                "    authorisation policy:/roles/surveyor/auth",
                "  aggregator  1..1  needs resources [communication] and tasks [Aggregator]",
                "    policy policy:/roles/aggregator/mission",
                "    authorisation policy:/roles/aggregator/auth",
                "  hdetector   2..2  secondary to surveyor  needs resources [chemical, motion] and tasks [HazardDetector]",
                "    policy policy:/roles/hdetector/mission",
                "    authorisation policy:/roles/hdetector/auth",
                "  relay       2..2  secondary to surveyor  needs resources [communication, motion] and tasks [Relay]",
                "    policy policy:/roles/relay/mission",
                "    authorisation policy:/roles/relay/auth",
                "management tree:",
                "  commander",
                "    surveyor",
                "      hdetector",
                "      relay",
                "    aggregator",
                "colocation:",
                "  relay runs in parallel with surveyor or hdetector",
                "  surveyor and hdetector share a vehicle, one active at a time"), result.outLines());
    }

    @Test
    void invalidInstance_listsEveryErrorAsFileLineCol_andExitStatusIs1() throws Exception {
        String instance = writeRescueCopy(Files.readString(PROJECT.resolve("missions/rescue.instance.xml"))
                .replace("<comTimeout>500</comTimeout>", "<comTimeout>soon</comTimeout>")
                .replace("<minimal>1</minimal>", "<minimal>4</minimal>"));

        Smc.Result result = smc.run("validate", "--repository", REPOSITORY, instance);

        assertEquals(List.of(
                instance + ":12:21: <comTimeout>: 'soon' is not an int; parameter 'comTimeout' is declared int in class 'Rescue'",
                instance + ":24:22: <minimal>: minimal 4 is more than optimal 1; the minimal cardinality is at most "
                        + "the reasonably-optimal one"), result.errLines());
        assertEquals("", result.out());
        assertEquals(1, result.status());
    }

    /**
     * A management chain of 3,000 roles is a valid tree: it validates, and the listing indents
     * the first levels and names the level of deeper roles (the tree was walked by recursion, and
     * such a chain overflowed the stack; each role's depth was found by a scan of every role).
     */
    @Test
    void aChainOfThousandsOfManagers_validates_andIsListed() throws Exception {
        int n = 3000;
        StringBuilder cls = new StringBuilder("<xml><missionClassParameters><missionClassName>Chain</missionClassName>"
                + "</missionClassParameters><constraints><cardinality/><colocation/></constraints><missionParameters>"
                + "<comTimeout>int</comTimeout><failureTimeout>int</failureTimeout></missionParameters>\n"
                + "<commanderBehaviour><roleManagement><manages>r1</manages></roleManagement></commanderBehaviour>\n");
        StringBuilder instance = new StringBuilder("<xml><missionInstanceParameters><missionInstanceName>C</missionInstanceName>"
                + "<missionClass href=\"chain.class.xml\">Chain</missionClass></missionInstanceParameters><missionParameters>"
                + "<comTimeout>500</comTimeout><failureTimeout>3000</failureTimeout></missionParameters>\n"
                + "<commander><policy>policy:/roles/commander/mission</policy></commander>\n");
        for (int i = 1; i <= n; i++) {
            cls.append("<r").append(i).append("Behaviour><roleManagement>")
                    .append(i < n ? "<manages>r" + (i + 1) + "</manages>" : "").append("</roleManagement></r").append(i).append("Behaviour>\n");
            instance.append("<r").append(i).append("><policy>policy:/roles/relay/mission</policy></r").append(i).append(">\n");
        }
        smc.file("chain.class.xml", cls.append("</xml>\n").toString());
        String file = smc.file("chain.instance.xml", instance.append("</xml>\n").toString());

        Smc.Result result = smc.run("validate", "--repository", REPOSITORY, file);

        assertEquals(0, result.status(), result.err());
        List<String> lines = result.out().lines().toList();
        assertTrue(lines.contains("  " + "  ".repeat(20) + "r20"), "level 20 indented");
        assertTrue(lines.contains("  " + "  ".repeat(20) + "r3000  (level 3000)"), "the deepest role names its level");
    }

    @Test
    void anAllowPathThatIsNoFolder_orAnEmptyInstanceName_isAUsageError() {
        Smc.Result noFolder = smc.run("validate", "--repository", REPOSITORY, "--allow-path", "nowhere",
                PROJECT.resolve("missions/reconnaissance.instance.xml").toString());
        assertEquals(2, noFolder.status(), noFolder.err());
        assertTrue(noFolder.err().contains("--allow-path 'nowhere': no such folder"), noFolder.err());

        Smc.Result empty = smc.run("validate", "--repository", REPOSITORY, "");
        assertEquals(2, empty.status(), empty.err());
        assertTrue(empty.err().contains("a file name is empty"), empty.err());
    }

    @Test
    void classOutsideTheInstancesFolder_isRefusedUnlessAllowedWithAllowPath() throws Exception {
        Files.createDirectories(dir.resolve("classes"));
        Files.copy(PROJECT.resolve("missions/rescue.class.xml"), dir.resolve("classes/rescue.class.xml"));
        Files.createDirectories(dir.resolve("instances"));
        String instance = smc.file("instances/rescue.instance.xml", Files.readString(PROJECT.resolve("missions/rescue.instance.xml"))
                .replace("href=\"rescue.class.xml\"", "href=\"../classes/rescue.class.xml\""));

        Smc.Result refused = smc.run("validate", "--repository", REPOSITORY, instance);
        Smc.Result allowed = smc.run("validate", "--repository", REPOSITORY, "--allow-path", "classes", instance);
        Smc.Result system = smc.run("validate", "--repository", REPOSITORY, smc.file("evil.instance.xml",
                Files.readString(PROJECT.resolve("missions/rescue.instance.xml")).replace("href=\"rescue.class.xml\"",
                        "href=\"../../../../../../../../../etc/passwd\"")));

        assertEquals(1, refused.status(), refused.err());
        assertTrue(refused.err().contains("refused mission class '../classes/rescue.class.xml': it is outside the "
                + "instance's folder"), refused.err());
        assertEquals(0, allowed.status(), allowed.err());
        assertEquals(1, system.status(), system.err());
        assertEquals(1, system.errLines().size(), system.err());
        assertTrue(system.err().contains("refused mission class '../../../../../../../../../etc/passwd'"), system.err());
        assertTrue(!system.err().contains("root"), "nothing of /etc/passwd is shown: " + system.err());
    }

    @Test
    void errorInTheClassFile_namesTheClassFile() throws Exception {
        String instance = writeRescueCopy(Files.readString(PROJECT.resolve("missions/rescue.instance.xml")));
        Path classFile = dir.resolve("rescue.class.xml");
        Files.writeString(classFile, Files.readString(classFile).replace("<manages>aggregator</manages>",
                "<manages>aggregator</manages><manages>medic</manages>"));

        Smc.Result result = smc.run("validate", "--repository", REPOSITORY, instance);

        assertEquals(1, result.errLines().size(), result.err());
        assertTrue(result.err().startsWith(classFile + ":24:42: "), result.err());
        assertTrue(result.err().contains("<manages>: unknown role 'medic'"), result.err());
        assertEquals(1, result.status());
    }

    @Test
    void relativeInstanceName_resolvesAgainstTheWorkingDirectory() throws Exception {
        writeRescueCopy(Files.readString(PROJECT.resolve("missions/rescue.instance.xml")));

        Smc.Result result = smc.run("validate", "--repository", REPOSITORY, "rescue.instance.xml");

        assertEquals(0, result.status(), result.err());
        assertEquals("mission WoundedSoldier (class Rescue)", result.outLines().get(0));
    }

    @Test
    void missingFile_isAUsageError_exitStatus2() {
        Smc.Result result = smc.run("validate", "--repository", REPOSITORY, "nowhere.instance.xml");

        assertEquals(2, result.status());
        assertTrue(result.err().startsWith("smc validate: cannot read 'nowhere.instance.xml': no such file\n"), result.err());
        assertEquals("", result.out());
    }

    @Test
    void noRepository_isAUsageError_exitStatus2() throws Exception {
        String instance = writeRescueCopy(Files.readString(PROJECT.resolve("missions/rescue.instance.xml")));

        Smc.Result result = smc.run("validate", instance);

        assertEquals(2, result.status());
        assertTrue(result.err().startsWith("smc validate: no --repository given and no policies/ folder in the current "
                + "directory; policy URIs need a repository to resolve in\n"), result.err());
    }

    @Test
    void noInstance_isAUsageError_exitStatus2() {
        Smc.Result result = smc.run("validate");

        assertEquals(2, result.status());
        assertTrue(result.err().startsWith("smc validate: Missing required parameter: 'INSTANCE.xml'"), result.err());
    }

    @Test
    void help_explainsTheExitStatuses() {
        Smc.Result result = smc.run("validate", "--help");

        assertEquals(0, result.status());
        assertTrue(result.out().startsWith("Usage: smc validate "), result.out());
        assertTrue(result.out().contains("1   the instance or its class breaks a rule"), result.out());
    }

    @Test
    void smcHelp_listsValidate() {
        assertTrue(smc.run("--help").out().contains("validate"));
    }
}
