package net.smc.core.team;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import net.smc.core.capability.CapabilitySummary;
import net.smc.core.mission.Mission;
import net.smc.core.mission.MissionLoader;
import net.smc.policy.api.PolicyRepository;
import org.junit.jupiter.api.Test;

/** The missions under missions/, loaded against the real repository, planned for the paper's teams. */
class ShippedMissionsPlanTest {
    private static final Path MISSIONS = Path.of(System.getProperty("smc.project.dir", "../")).resolve("missions");
    private static final PolicyRepository REPOSITORY =
            new PolicyRepository(Path.of(System.getProperty("smc.repo.dir", "../policies")));

    private static Mission load(String file) throws Exception {
        return new MissionLoader(REPOSITORY).load(MISSIONS.resolve(file));
    }

    private static CapabilitySummary robot(String id) {
        // the rescue's robots (net.smc.sim.scenario.RescueScenario): they navigate, assist and aggregate
        return Fixtures.vehicle(id, Set.of("motion", "video", "communication"), Set.of("Navigator", "Assist", "Aggregator"));
    }

    @Test
    void rescue_laptopCommands_oneRobotSurveys_theOtherAggregates() throws Exception {
        Mission rescue = load("rescue.instance.xml");

        TeamConfiguration team = TeamPlanner.plan(rescue,
                List.of(Fixtures.commanderVehicle("laptop"), robot("koala1"), robot("koala2")), "laptop");

        assertEquals(Map.of("laptop", List.of("commander"), "koala1", List.of("surveyor"), "koala2", List.of("aggregator")),
                team.rolesByVehicle());
        assertTrue(team.optimalReached());
    }

    @Test
    void rescue_whenTheSurveyorFails_theAggregatorsVehicleBecomesSurveyor() throws Exception {
        Mission rescue = load("rescue.instance.xml");
        List<CapabilitySummary> vehicles = new ArrayList<>(List.of(Fixtures.commanderVehicle("laptop"), robot("koala2")));

        TeamConfiguration team = TeamPlanner.plan(rescue, vehicles, "laptop");

        assertEquals(List.of("surveyor"), team.rolesOf("koala2"));
        assertEquals(List.of(), team.holdersOf("aggregator"));
        assertTrue(team.minimalMet(), "the team contracts to its minimal form and goes on");
    }

    @Test
    void reconnaissance_fourVehiclesGiveFig1_eightGiveFig2() throws Exception {
        Mission reconnaissance = load("reconnaissance.instance.xml");
        List<CapabilitySummary> vehicles = new ArrayList<>(List.of(Fixtures.commanderVehicle("c0"),
                Fixtures.aggregatorVehicle("a0"), Fixtures.allRounder("s0"), Fixtures.allRounder("s1")));

        TeamConfiguration fig1 = TeamPlanner.plan(reconnaissance, vehicles, "c0");
        vehicles.addAll(List.of(Fixtures.relayVehicle("r0"), Fixtures.relayVehicle("r1"),
                Fixtures.detectorVehicle("h0"), Fixtures.detectorVehicle("h1")));
        TeamConfiguration fig2 = TeamPlanner.plan(reconnaissance, vehicles, "c0");

        assertEquals(List.of("surveyor", "hdetector", "relay"), fig1.rolesOf("s0"));
        assertTrue(fig1.minimalMet() && !fig1.optimalReached());
        assertEquals(List.of("surveyor"), fig2.rolesOf("s0"));
        assertTrue(fig2.optimalReached());
    }
}
