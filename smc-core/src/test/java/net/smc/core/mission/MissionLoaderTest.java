package net.smc.core.mission;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import net.smc.core.capability.CapabilityRequirement;
import net.smc.policy.api.PolicyRepository;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class MissionLoaderTest {
    /** The paper's Table III with its typos corrected and its comment line made a comment. */
    static final String TABLE_III = """
            <!--Mission Class Specification-->
            <xml>
            <missionClassParameters>
                <missionClassName>Reconnaissance
                </missionClassName>
            </missionClassParameters>
            <constraints>
                <cardinality/>
                <colocation/>
            </constraints>
            <missionParameters>
               <!--A mission class instance should provide values
                for these parameters-->
                <comTimeout> int</comTimeout>
                <failureTimeout>int</failureTimeout>
            </missionParameters>
            <commanderBehaviour>
                <roleManagement>
                    <manages>surveyor</manages>
                    <manages>aggregator</manages>
                </roleManagement>
            </commanderBehaviour>
            <surveyorBehaviour>
                <cardinality>int</cardinality>
                <roleManagement>
                    <manages>hdetector</manages>
                    <manages>relay</manages>
                </roleManagement>
            </surveyorBehaviour>
            <aggregatorBehaviour>
                <cardinality>int</cardinality>
                <roleManagement/>
            </aggregatorBehaviour>
            <hdetectorBehaviour>
                <cardinality>int</cardinality>
                <roleManagement/>
            </hdetectorBehaviour>
            <relayBehaviour>
                <cardinality>int</cardinality>
                <roleManagement/>
            </relayBehaviour>
            </xml>
            """;

    @TempDir
    Path dir;

    private MissionLoader loader;

    @BeforeEach
    void setUp() throws IOException {
        for (String role : List.of("commander", "surveyor", "aggregator", "hdetector", "relay")) {
            write("policies/roles/" + role + "/mission.p2", "root print: \"" + role + "\".\n");
        }
        loader = new MissionLoader(new PolicyRepository(dir.resolve("policies")));
    }

    private Path write(String name, String text) throws IOException {
        Path file = dir.resolve(name);
        Files.createDirectories(file.getParent());
        Files.writeString(file, text);
        return file;
    }

    private static String role(String name, int minimal, int optimal) {
        return "<" + name + "><cardinality><minimal>" + minimal + "</minimal><optimal>" + optimal + "</optimal></cardinality>"
                + "<policy>policy:/roles/" + name + "/mission</policy></" + name + ">\n";
    }

    private static String reconnaissanceInstance(String href) {
        return "<xml>\n<missionInstanceParameters><missionInstanceName>Test</missionInstanceName>"
                + "<missionClass href=\"" + href + "\">Reconnaissance</missionClass></missionInstanceParameters>\n"
                + "<missionParameters><comTimeout>500</comTimeout><failureTimeout>3000</failureTimeout></missionParameters>\n"
                + "<commander><policy>policy:/roles/commander/mission</policy></commander>\n"
                + role("surveyor", 2, 2) + role("aggregator", 1, 1) + role("hdetector", 0, 2) + role("relay", 0, 2)
                + "</xml>\n";
    }

    @Test
    void tableIII_asWrittenWithTyposCorrected_isAccepted() throws Exception {
        write("reconnaissance.class.xml", TABLE_III);
        Path instance = write("reconnaissance.instance.xml", reconnaissanceInstance("reconnaissance.class.xml"));

        Mission mission = loader.load(instance);

        assertEquals("Reconnaissance", mission.className());
        assertEquals(List.of("commander", "surveyor", "aggregator", "hdetector", "relay"), mission.roleNames());
        assertEquals(List.of("hdetector", "relay"), mission.tree().childrenOf("surveyor"));
        assertEquals(500, mission.parameter("comTimeout").orElseThrow().asInt());
        assertEquals(CapabilityRequirement.none(), mission.role("relay").orElseThrow().requirement());
        assertEquals(Colocation.none(), mission.colocation());
    }

    @Test
    void roleWithoutCardinalityInItsClass_hasExactlyOneHolder() throws Exception {
        write("reconnaissance.class.xml", TABLE_III);
        Path instance = write("reconnaissance.instance.xml", reconnaissanceInstance("reconnaissance.class.xml"));

        MissionRole commander = loader.load(instance).commander();

        assertEquals(1, commander.minimal());
        assertEquals(1, commander.optimal());
    }

    @Test
    void classHref_resolvesRelativeToTheInstanceFile() throws Exception {
        write("instances/classes/reconnaissance.class.xml", TABLE_III);
        Path instance = write("instances/house.instance.xml", reconnaissanceInstance("classes/reconnaissance.class.xml"));

        assertEquals("Reconnaissance", loader.load(instance).className());
    }

    @Test
    void classHref_outsideTheInstancesFolder_isRefusedUnread_unlessItsFolderIsAllowed() throws Exception {
        write("classes/reconnaissance.class.xml", TABLE_III);
        Path instance = write("instances/house.instance.xml", reconnaissanceInstance("../classes/reconnaissance.class.xml"));

        MissionException e = assertThrows(MissionException.class, () -> loader.load(instance));

        assertEquals(1, e.errors().size(), e.getMessage());
        assertTrue(e.errors().get(0).message().contains("refused mission class '../classes/reconnaissance.class.xml': "
                + "it is outside the instance's folder"), e.getMessage());
        MissionLoader allowing = new MissionLoader(new PolicyRepository(dir.resolve("policies")),
                List.of(dir.resolve("classes")));
        assertEquals("Reconnaissance", allowing.load(instance).className());
    }

    @Test
    void classHref_toSystemFiles_isRefusedWithoutEchoingThem() throws Exception {
        for (String href : List.of("../../../../../../../../etc/passwd", "/etc/passwd", "/proc/self/environ")) {
            Path instance = write("house.instance.xml", reconnaissanceInstance(href));

            MissionException e = assertThrows(MissionException.class, () -> loader.load(instance));

            assertEquals(1, e.errors().size(), e.getMessage());
            String message = e.errors().get(0).message();
            assertTrue(message.startsWith("refused mission class '" + href + "': it is outside"), message);
            assertFalse(message.contains("root"), "nothing of the file is shown: " + message);
        }
    }

    @Test
    void classHref_throughASymbolicLinkOutOfTheFolder_isRefused() throws Exception {
        write("elsewhere/reconnaissance.class.xml", TABLE_III);
        Files.createDirectories(dir.resolve("instances"));
        Files.createSymbolicLink(dir.resolve("instances/link.class.xml"), dir.resolve("elsewhere/reconnaissance.class.xml"));
        Path instance = write("instances/house.instance.xml", reconnaissanceInstance("link.class.xml"));

        MissionException e = assertThrows(MissionException.class, () -> loader.load(instance));

        assertTrue(e.getMessage().contains("it is outside the instance's folder"), e.getMessage());
    }

    @Test
    void overlongText_isRefusedWithItsElementAndLimit() throws Exception {
        write("reconnaissance.class.xml", TABLE_III);
        Path instance = write("reconnaissance.instance.xml", reconnaissanceInstance("reconnaissance.class.xml")
                .replace("<missionInstanceName>Test", "<missionInstanceName>" + "T".repeat(5000)));

        MissionException e = assertThrows(MissionException.class, () -> loader.load(instance));

        assertEquals(1, e.errors().size(), e.getMessage());
        assertTrue(e.errors().get(0).toString().contains(":2:28: <missionInstanceName>: its text is longer than 4096 "
                + "characters"), e.getMessage());
    }

    @Test
    void overlongAttribute_andOversizedFile_areRefused() throws Exception {
        write("reconnaissance.class.xml", TABLE_III);
        Path instance = write("reconnaissance.instance.xml", reconnaissanceInstance("x".repeat(5000)));
        MissionException e = assertThrows(MissionException.class, () -> loader.load(instance));
        assertTrue(e.getMessage().contains("attribute 'href' has 5000 characters; an attribute value may have at most 4096"),
                e.getMessage());

        Path huge = write("huge.instance.xml", "<xml>" + " ".repeat((int) MissionLoader.MAX_FILE_BYTES) + "</xml>");
        IOException tooBig = assertThrows(IOException.class, () -> loader.load(huge));
        assertTrue(tooBig.getMessage().contains("is larger than the limit of 1048576 bytes"), tooBig.getMessage());
    }

    @Test
    void everyErrorOfBothFiles_isReported_classFirst_eachFileByPosition() throws Exception {
        write("reconnaissance.class.xml", TABLE_III.replace("<manages>aggregator</manages>", "<manages>pilot</manages>")
                .replace("<failureTimeout>int</failureTimeout>", "<failureTimeout>number</failureTimeout>"));
        Path instance = write("reconnaissance.instance.xml", reconnaissanceInstance("reconnaissance.class.xml")
                .replace("<comTimeout>500</comTimeout>", "<comTimeout>soon</comTimeout>")
                .replace("<minimal>2</minimal><optimal>2</optimal>", "<minimal>3</minimal><optimal>2</optimal>"));

        MissionException e = assertThrows(MissionException.class, () -> loader.load(instance));

        assertEquals(List.of(
                "reconnaissance.class.xml:15:21: <failureTimeout>: unknown parameter type 'number'",
                "reconnaissance.class.xml:20:9: <manages>: unknown role 'pilot'",
                "reconnaissance.class.xml:30:1: <aggregatorBehaviour>: role 'aggregator' has no manager",
                "reconnaissance.instance.xml:3:32: <comTimeout>: 'soon' is not an int",
                "reconnaissance.instance.xml:5:33: <minimal>: minimal 3 is more than optimal 2"),
                e.errors().stream().map(err -> dir.relativize(err.file()) + ":" + err.line() + ":" + err.column()
                        + ": <" + err.element() + ">: " + err.message().substring(0, err.message().indexOf(';'))).toList());
    }

    @Test
    void missionError_printsAsFileLineColumnElementMessage() {
        MissionError error = new MissionError(Path.of("m.xml"), 3, 7, "manages", "unknown role 'x'; rule");

        assertEquals("m.xml:3:7: <manages>: unknown role 'x'; rule", error.toString());
        assertEquals("m.xml:1:2: not well-formed XML: oops",
                new MissionError(Path.of("m.xml"), 1, 2, null, "not well-formed XML: oops").toString());
    }

    @Test
    void missionException_messageListsEveryError() throws Exception {
        write("reconnaissance.class.xml", TABLE_III);
        Path instance = write("reconnaissance.instance.xml", reconnaissanceInstance("reconnaissance.class.xml")
                .replace("<comTimeout>500</comTimeout>", "<comTimeout>x</comTimeout>")
                .replace("<failureTimeout>3000</failureTimeout>", "<failureTimeout>y</failureTimeout>"));

        MissionException e = assertThrows(MissionException.class, () -> loader.load(instance));

        assertTrue(e.getMessage().startsWith("2 errors in mission files:\n"), e.getMessage());
        assertTrue(e.getMessage().contains("'x' is not an int") && e.getMessage().contains("'y' is not an int"), e.getMessage());
    }

    /** Blank lines between elements are layout, not text: they count against no element's text limit. */
    @Test
    void blankLinesBetweenElements_areNotText() throws Exception {
        write("reconnaissance.class.xml", TABLE_III);
        Path instance = write("reconnaissance.instance.xml", reconnaissanceInstance("reconnaissance.class.xml")
                .replace("<missionParameters>", "\n".repeat(5000) + "<missionParameters>"));

        assertEquals("Test", loader.load(instance).instanceName());
    }

    /** An instance file that is not UTF-8 is refused naming the first bad byte, its offset and line. */
    @Test
    void anInstanceFileNotInUtf8_isRefusedNamingItsFirstBadByte() throws Exception {
        write("reconnaissance.class.xml", TABLE_III);
        Path instance = dir.resolve("latin1.instance.xml");
        Files.write(instance, reconnaissanceInstance("reconnaissance.class.xml").replace("<xml>", "<?xml version=\"1.0\" "
                + "encoding=\"ISO-8859-1\"?>\n<!-- Caf\u00e9 -->\n<xml>").getBytes(java.nio.charset.StandardCharsets.ISO_8859_1));

        IOException e = assertThrows(IOException.class, () -> loader.load(instance));

        assertEquals("not valid UTF-8: byte 0xE9 at byte offset 52 (line 2) is not part of a well-formed character; save "
                + "the file as UTF-8 (or as UTF-16 with a byte-order mark)", e.getMessage());
    }

    /** An include beside the including file may not leave the repository (an absolute path, or one through ..). */
    @Test
    void policyIncludeOutsideTheRepository_isNotRead() throws Exception {
        Path outside = write("secret.p2", "root print: \"secret\".\n");
        write("policies/roles/relay/mission.p2", "include \"" + outside.toAbsolutePath() + "\".\ninclude \"../../../secret.p2\".\n");
        write("reconnaissance.class.xml", TABLE_III);
        Path instance = write("reconnaissance.instance.xml", reconnaissanceInstance("reconnaissance.class.xml"));

        MissionException e = assertThrows(MissionException.class, () -> loader.load(instance));

        assertEquals(1, e.errors().size(), e.getMessage());
        assertTrue(e.errors().get(0).message().startsWith("policy 'policy:/roles/relay/mission' does not parse: ")
                && e.errors().get(0).message().contains("it is outside the policy repository")
                && e.errors().get(0).message().contains("(and 1 more)"), e.getMessage());
    }

    @Test
    void missingInstanceFile_isAnIOException_notAMissionError() {
        assertThrows(NoSuchFileException.class, () -> loader.load(dir.resolve("nowhere.instance.xml")));
    }

    @Test
    void policyIncludes_resolveBesideTheIncludingFile() throws Exception {
        write("policies/roles/relay/common.p2", "root print: \"shared\".\n");
        write("policies/roles/relay/mission.p2", "include \"common.p2\".\nroot print: \"relay\".\n");
        write("reconnaissance.class.xml", TABLE_III);
        Path instance = write("reconnaissance.instance.xml", reconnaissanceInstance("reconnaissance.class.xml"));

        assertEquals(List.of("policy:/roles/relay/mission"), loader.load(instance).role("relay").orElseThrow().policies());
    }

    @Test
    void policyIncludingAMissingFile_isReportedAsNotParsing() throws Exception {
        write("policies/roles/relay/mission.p2", "include \"nowhere.p2\".\n");
        write("reconnaissance.class.xml", TABLE_III);
        Path instance = write("reconnaissance.instance.xml", reconnaissanceInstance("reconnaissance.class.xml"));

        MissionException e = assertThrows(MissionException.class, () -> loader.load(instance));

        assertEquals(1, e.errors().size(), e.getMessage());
        assertTrue(e.errors().get(0).message().startsWith("policy 'policy:/roles/relay/mission' does not parse: "),
                e.getMessage());
    }

    /** A vehicle that takes the role gets its files in one policy reply each, so none may be longer than a reply carries. */
    @Test
    void aPolicyLongerThanAPolicyReplyCarries_isRefusedNamingItsSize_oneAtTheLimitLoads() throws Exception {
        String line = "root print: \"" + "x".repeat(84) + "\".\n";   // 100 bytes
        write("policies/roles/relay/mission.p2", line.repeat(650));    // 65,000 bytes: the limit
        write("reconnaissance.class.xml", TABLE_III);
        Path instance = write("reconnaissance.instance.xml", reconnaissanceInstance("reconnaissance.class.xml"));
        assertEquals(List.of("policy:/roles/relay/mission"), loader.load(instance).role("relay").orElseThrow().policies());

        write("policies/roles/relay/mission.p2", line.repeat(650) + "\n");
        MissionException e = assertThrows(MissionException.class, () -> new MissionLoader(new PolicyRepository(dir.resolve("policies"))).load(instance));
        assertEquals(1, e.errors().size(), e.getMessage());
        assertEquals("policy 'policy:/roles/relay/mission' is 65001 bytes of text; a policy file must be at most 65000 "
                + "bytes, what one policy reply carries to a vehicle that takes the role (split it into several files)",
                e.errors().get(0).message());
    }

    @Test
    void dtd_isRefused() throws Exception {
        write("reconnaissance.class.xml", TABLE_III);
        Path instance = write("reconnaissance.instance.xml", "<!DOCTYPE xml [<!ENTITY x SYSTEM \"file:///etc/passwd\">]>\n"
                + reconnaissanceInstance("reconnaissance.class.xml").replace("<missionInstanceName>Test", "<missionInstanceName>&x;"));

        MissionException e = assertThrows(MissionException.class, () -> loader.load(instance));

        assertEquals(1, e.errors().size(), e.getMessage());
        assertTrue(e.errors().get(0).toString().contains(":1:1: a DOCTYPE declaration is not allowed"), e.getMessage());
    }

    @Test
    void externalDtd_isRefusedWithItsPosition() throws Exception {
        write("reconnaissance.class.xml", TABLE_III);
        Path instance = write("reconnaissance.instance.xml", "<?xml version=\"1.0\"?>\n"
                + "<!DOCTYPE xml SYSTEM \"http://example.invalid/mission.dtd\">\n"
                + reconnaissanceInstance("reconnaissance.class.xml"));

        MissionException e = assertThrows(MissionException.class, () -> loader.load(instance));

        assertEquals(1, e.errors().size(), e.getMessage());
        assertTrue(e.errors().get(0).toString().contains(":2:1: a DOCTYPE declaration is not allowed"), e.getMessage());
    }

    @Test
    void secondaryRole_getsItsPrimaryFromTheColocationRules() throws Exception {
        write("reconnaissance.class.xml", TABLE_III.replace("<colocation/>",
                "<colocation><parallel role=\"relay\" with=\"surveyor\"/><secondary role=\"relay\" primary=\"surveyor\"/></colocation>"));
        Path instance = write("reconnaissance.instance.xml", reconnaissanceInstance("reconnaissance.class.xml"));

        Mission mission = loader.load(instance);

        assertEquals(Optional.of("surveyor"), mission.role("relay").orElseThrow().primary());
        assertEquals(Optional.empty(), mission.role("hdetector").orElseThrow().primary());
    }
}
