package net.smc.core.team;

import static net.smc.core.team.Fixtures.aggregatorVehicle;
import static net.smc.core.team.Fixtures.allRounder;
import static net.smc.core.team.Fixtures.commanderVehicle;
import static net.smc.core.team.Fixtures.detectorVehicle;
import static net.smc.core.team.Fixtures.relayVehicle;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import net.smc.core.capability.CapabilitySummary;
import net.smc.core.mission.Colocation;
import net.smc.core.mission.Mission;
import org.junit.jupiter.api.Test;

/** The reconnaissance of section II-A: Fig. 1 (minimal) to Fig. 2 (reasonably-optimal) and back. */
class TeamPlannerTest {
    private final Mission reconnaissance = Fixtures.reconnaissance();

    private List<CapabilitySummary> fig1() {
        return new ArrayList<>(List.of(commanderVehicle("c0"), aggregatorVehicle("a0"), allRounder("s0"), allRounder("s1")));
    }

    @Test
    void fourVehicles_meetTheMinimalConfigurationOfFig1() {
        TeamConfiguration team = TeamPlanner.plan(reconnaissance, fig1());

        assertEquals(Map.of("c0", List.of("commander"), "a0", List.of("aggregator"),
                "s0", List.of("surveyor", "hdetector", "relay"), "s1", List.of("surveyor", "hdetector", "relay")),
                team.rolesByVehicle());
        assertTrue(team.minimalMet());
        assertFalse(team.optimalReached());
        assertEquals(List.of(), team.spare());
        assertEquals(Optional.of("c0"), team.commander());
    }

    @Test
    void eightVehicles_reachTheReasonablyOptimalConfigurationOfFig2() {
        List<CapabilitySummary> vehicles = fig1();
        vehicles.addAll(List.of(relayVehicle("r0"), relayVehicle("r1"), detectorVehicle("h0"), detectorVehicle("h1")));

        TeamConfiguration team = TeamPlanner.plan(reconnaissance, vehicles);

        assertEquals(List.of("s0", "s1"), team.holdersOf("surveyor"));
        assertEquals(List.of("h0", "h1"), team.holdersOf("hdetector"));
        assertEquals(List.of("r0", "r1"), team.holdersOf("relay"));
        assertEquals(List.of("surveyor"), team.rolesOf("s0"));
        assertTrue(team.minimalMet());
        assertTrue(team.optimalReached());
    }

    @Test
    void relayJoining_takesTheRelayRoleOffOneSurveyor() {
        List<CapabilitySummary> vehicles = fig1();
        vehicles.add(relayVehicle("r0"));

        TeamConfiguration team = TeamPlanner.plan(reconnaissance, vehicles);

        assertEquals(List.of("relay"), team.rolesOf("r0"));
        assertEquals(List.of("r0", "s0"), team.holdersOf("relay"));
        assertEquals(List.of("surveyor", "hdetector"), team.rolesOf("s1"));
    }

    @Test
    void relayLeaving_givesTheRoleBackToASurveyor() {
        List<CapabilitySummary> vehicles = fig1();
        vehicles.add(relayVehicle("r0"));
        TeamPlanner.plan(reconnaissance, vehicles);

        vehicles.removeIf(v -> v.vehicle().equals("r0"));
        TeamConfiguration team = TeamPlanner.plan(reconnaissance, vehicles);

        assertEquals(List.of("s0", "s1"), team.holdersOf("relay"));
        assertEquals(List.of("surveyor", "hdetector", "relay"), team.rolesOf("s1"));
    }

    @Test
    void oneSurveyorShort_minimalIsNotMet_butWhatCanBeHeldIsHeld() {
        List<CapabilitySummary> vehicles = fig1();
        vehicles.removeIf(v -> v.vehicle().equals("s1"));

        TeamConfiguration team = TeamPlanner.plan(reconnaissance, vehicles);

        assertFalse(team.minimalMet());
        assertEquals(List.of("s0"), team.holdersOf("surveyor"));
        assertEquals(List.of("c0"), team.holdersOf("commander"));
    }

    @Test
    void surplusVehicles_areSpare() {
        List<CapabilitySummary> vehicles = fig1();
        vehicles.add(Fixtures.vehicle("x0", Set.of("video"), Set.of()));
        vehicles.add(allRounder("s2"));

        TeamConfiguration team = TeamPlanner.plan(reconnaissance, vehicles);

        assertEquals(List.of("x0"), team.spare());
        assertEquals(List.of("hdetector"), team.rolesOf("s2"), "a spare all-rounder takes a secondary role of its own");
    }

    @Test
    void actingCommander_holdsTheCommanderRole() {
        TeamConfiguration team = TeamPlanner.plan(reconnaissance, fig1(), "a0");

        assertEquals(List.of("commander"), team.rolesOf("a0"));
        assertFalse(team.minimalMet(), "c0 cannot aggregate, so nobody is left to");
    }

    @Test
    void withoutActingCommander_theCommanderIsTheVehicleOtherRolesNeedLeast() {
        List<CapabilitySummary> vehicles = fig1();
        vehicles.add(0, commanderVehicle("b0"));

        TeamConfiguration team = TeamPlanner.plan(reconnaissance, vehicles);

        assertEquals(Optional.of("b0"), team.commander(), "b0 and c0 can only command; b0 comes first by id");
    }

    @Test
    void exactSearch_findsTheMinimalConfigurationGreedWouldMiss() {
        // v0 can command or aggregate, v1 only command: the least flexible vehicle goes first, but
        // here the search must back out when a role cannot be filled.
        Mission mission = new Mission("M", "m", List.of(
                Fixtures.role("commander", 1, 1, List.of("a", "b"), null, Set.of("x"), Set.of()),
                Fixtures.role("a", 1, 1, List.of(), null, Set.of("y"), Set.of()),
                Fixtures.role("b", 1, 1, List.of(), null, Set.of("x", "y"), Set.of())), Colocation.none(), Map.of());
        List<CapabilitySummary> vehicles = List.of(Fixtures.vehicle("v0", Set.of("x", "y"), Set.of()),
                Fixtures.vehicle("v1", Set.of("x"), Set.of()), Fixtures.vehicle("v2", Set.of("x", "y"), Set.of()));

        TeamConfiguration team = TeamPlanner.plan(mission, vehicles);

        assertTrue(team.minimalMet(), team.toString());
        assertEquals(List.of("v1"), team.holdersOf("commander"));
    }

    @Test
    void actingCommanderNotAmongTheVehicles_isRejected() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> TeamPlanner.plan(reconnaissance, fig1(), "ghost"));

        assertEquals("acting commander 'ghost' is not among the vehicles", e.getMessage());
    }

    @Test
    void actingCommanderLackingTheRequirement_isRejected() {
        List<CapabilitySummary> vehicles = fig1();
        vehicles.add(detectorVehicle("h0"));

        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> TeamPlanner.plan(reconnaissance, vehicles, "h0"));

        assertEquals("acting commander 'h0' lacks resources [communication]; the commander role requires "
                + "resources [communication]", e.getMessage());
    }

    @Test
    void twoVehiclesWithOneId_areRejected() {
        List<CapabilitySummary> vehicles = fig1();
        vehicles.add(relayVehicle("s0"));

        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> TeamPlanner.plan(reconnaissance, vehicles));

        assertEquals("two vehicles are called 's0'; vehicle ids are unique", e.getMessage());
    }

    @Test
    void noVehicles_meetNothing_andEveryRoleIsListedWithoutHolders() {
        TeamConfiguration team = TeamPlanner.plan(reconnaissance, List.of());

        assertFalse(team.minimalMet());
        assertEquals(reconnaissance.roleNames(), List.copyOf(team.holders().keySet()));
        assertTrue(team.holders().values().stream().allMatch(List::isEmpty));
    }

    @Test
    void configuration_isImmutable() {
        TeamConfiguration team = TeamPlanner.plan(reconnaissance, fig1());

        assertThrows(UnsupportedOperationException.class, () -> team.holders().get("surveyor").add("x"));
        assertThrows(UnsupportedOperationException.class, () -> team.assignments().clear());
    }
}
