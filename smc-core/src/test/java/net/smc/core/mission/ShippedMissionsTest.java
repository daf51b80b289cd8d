package net.smc.core.mission;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import javax.xml.XMLConstants;
import javax.xml.transform.stream.StreamSource;
import javax.xml.validation.Schema;
import javax.xml.validation.SchemaFactory;
import net.smc.core.capability.CapabilityRequirement;
import net.smc.policy.api.PolicyRepository;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.api.Test;

/** The missions under missions/ load against the real policy repository and match their XSDs. */
class ShippedMissionsTest {
    private static final Path MISSIONS = Path.of(System.getProperty("smc.project.dir", "../")).resolve("missions");
    private static final PolicyRepository REPOSITORY =
            new PolicyRepository(Path.of(System.getProperty("smc.repo.dir", "../policies")));

    private static Mission load(String file) throws Exception {
        return new MissionLoader(REPOSITORY).load(MISSIONS.resolve(file));
    }

    @Test
    void reconnaissance_hasTheRolesAndCardinalitiesOfSectionIIA() throws Exception {
        Mission mission = load("reconnaissance.instance.xml");

        assertEquals("Reconnaissance", mission.className());
        assertEquals("HouseSurvey", mission.instanceName());
        assertEquals(List.of("commander 1..1", "surveyor 2..2", "aggregator 1..1", "hdetector 2..2", "relay 2..2"),
                mission.roles().stream().map(r -> r.name() + " " + r.cardinality()).toList());
    }

    @Test
    void reconnaissance_managementTreeIsThatOfFig5() throws Exception {
        ManagementTree tree = load("reconnaissance.instance.xml").tree();

        assertEquals("commander", tree.root());
        assertEquals(List.of("surveyor", "aggregator"), tree.childrenOf("commander"));
        assertEquals(List.of("hdetector", "relay"), tree.childrenOf("surveyor"));
        assertEquals(List.of("commander", "surveyor", "hdetector", "relay", "aggregator"), tree.depthFirst());
        assertEquals(Optional.of("surveyor"), tree.parentOf("relay"));
        assertEquals(2, tree.depthOf("hdetector"));
    }

    @Test
    void reconnaissance_relayAndDetectorAreSecondaryToTheSurveyor() throws Exception {
        Mission mission = load("reconnaissance.instance.xml");

        assertEquals(Optional.of("surveyor"), mission.role("relay").orElseThrow().primary());
        assertEquals(Optional.of("surveyor"), mission.role("hdetector").orElseThrow().primary());
        assertFalse(mission.role("surveyor").orElseThrow().isSecondary());
        assertTrue(mission.colocation().runInParallel("relay", "hdetector"));
        assertTrue(mission.colocation().switchBetween("surveyor", "hdetector"));
        assertTrue(mission.allowsOnOneVehicle(List.of("surveyor", "relay", "hdetector")));
        assertFalse(mission.allowsOnOneVehicle(List.of("surveyor", "aggregator")));
        assertFalse(mission.allowsOnOneVehicle(List.of("relay", "hdetector")), "secondary roles need their primary");
    }

    /**
     * Events reach a vehicle only when one of its roles subscribes to them: the surveyors subscribe
     * to the maps they publish, so each fills its map from the others' whether or not it also holds
     * a detector's seat (which subscribes to them too), and does not map again what another mapped.
     */
    @Test
    void reconnaissance_surveyorsHearEachOthersMaps() throws Exception {
        Mission mission = load("reconnaissance.instance.xml");

        MissionRole surveyor = mission.role("surveyor").orElseThrow();
        assertTrue(surveyor.interfaces().publishes().contains("mapUpdate"), surveyor.interfaces()::toString);
        assertTrue(surveyor.interfaces().subscribes().contains("mapUpdate"), surveyor.interfaces()::toString);
    }

    /**
     * A surveyor tells of a failed teammate's body (failedBody) to the robots that drive through the
     * house: the other surveyors and the detectors subscribe to it.
     */
    @Test
    void reconnaissance_surveyorsTellSurveyorsAndDetectorsOfFailedBodies() throws Exception {
        Mission mission = load("reconnaissance.instance.xml");

        RoleInterface surveyor = mission.role("surveyor").orElseThrow().interfaces();
        RoleInterface detector = mission.role("hdetector").orElseThrow().interfaces();
        assertTrue(surveyor.publishes().contains("failedBody") && surveyor.subscribes().contains("failedBody"), surveyor::toString);
        assertTrue(detector.subscribes().contains("failedBody"), detector::toString);
    }

    @Test
    void reconnaissance_rolesCarryRequirementsAndPolicies() throws Exception {
        Mission mission = load("reconnaissance.instance.xml");

        MissionRole surveyor = mission.role("surveyor").orElseThrow();
        assertEquals(CapabilityRequirement.of(java.util.Set.of("motion", "video"), java.util.Set.of("Explorer")),
                surveyor.requirement());
        assertEquals(List.of("policy:/roles/surveyor/mission"), surveyor.policies());
        assertEquals(List.of("policy:/roles/surveyor/auth"), surveyor.authorisations());
        assertEquals(List.of("policy:/roles/commander/assign", "policy:/roles/commander/reassign",
                "policy:/roles/commander/mission"), mission.commander().policies());
    }

    @Test
    void reconnaissance_parametersAreTyped() throws Exception {
        Map<String, Parameter> parameters = load("reconnaissance.instance.xml").parameters();

        assertEquals(List.of("comTimeout", "failureTimeout", "scheme", "backups"), List.copyOf(parameters.keySet()));
        assertEquals(500, parameters.get("comTimeout").asInt());
        assertEquals(3000, parameters.get("failureTimeout").asInt());
        assertEquals("distributed", parameters.get("scheme").asString());
        assertEquals(1, parameters.get("backups").asInt());
    }

    @Test
    void rescue_hasCommanderSurveyorAndOptionalAggregator() throws Exception {
        Mission mission = load("rescue.instance.xml");

        assertEquals("Rescue", mission.className());
        assertEquals(List.of("commander 1..1", "surveyor 1..1", "aggregator 0..1"),
                mission.roles().stream().map(r -> r.name() + " " + r.cardinality()).toList());
        assertEquals(List.of("surveyor", "aggregator"), mission.tree().childrenOf("commander"));
        // Where the soldier is comes from the soldier's own distress call, not from the mission.
        assertTrue(mission.parameter("soldierX").isEmpty(), "no soldierX parameter");
        assertEquals(500, mission.parameter("comTimeout").orElseThrow().asInt());
        assertEquals(Duration.ZERO.plusMillis(2000).toMillis(), mission.parameter("failureTimeout").orElseThrow().asLong());
    }

    @ParameterizedTest
    @CsvSource({
        "mission-class.xsd, reconnaissance.class.xml",
        "mission-class.xsd, rescue.class.xml",
        "mission-instance.xsd, reconnaissance.instance.xml",
        "mission-instance.xsd, rescue.instance.xml"})
    void shippedFile_validatesAgainstItsSchema(String schema, String file) throws Exception {
        Schema xsd = SchemaFactory.newInstance(XMLConstants.W3C_XML_SCHEMA_NS_URI)
                .newSchema(MISSIONS.resolve(schema).toFile());

        xsd.newValidator().validate(new StreamSource(new File(MISSIONS.resolve(file).toString())));
    }
}
