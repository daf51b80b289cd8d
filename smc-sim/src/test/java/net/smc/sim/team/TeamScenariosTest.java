package net.smc.sim.team;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.math.BigDecimal;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.function.BooleanSupplier;

import net.smc.core.cell.Cell;
import net.smc.core.cell.MissionState;
import net.smc.core.cell.Seat;
import net.smc.core.cell.Missions;
import net.smc.core.message.Identity;
import net.smc.core.mission.Mission;
import org.junit.jupiter.api.Test;

/** Whole teams on the simulated network, one scenario each, checked against the invariants at every step. */
class TeamScenariosTest {
    private static final long FAILURE = 3_000;

    private static TeamSimulation sim(Mission mission, long seed, List<SimVehicle> vehicles, TeamSimulation.Security security) {
        return TeamSimulation.builder(mission, Missions.REPOSITORY, seed).vehicles(vehicles).security(security).build();
    }

    private static TeamSimulation sim(long seed, List<SimVehicle> vehicles) {
        return sim(Missions.reconnaissance(), seed, vehicles, TeamSimulation.Security.IDEAL);
    }

    private static void until(TeamSimulation sim, BooleanSupplier condition, long maxMillis, String what) {
        boolean reached;
        try {
            reached = sim.runUntil(condition, maxMillis);
        } catch (InvariantViolation v) {
            throw new AssertionError(v.report(), v);
        }
        assertTrue(reached, () -> what + " not reached within " + maxMillis + " ms (" + sim.invariants().unsettled()
                + ")\n" + String.join("\n", sim.trace()));
    }

    private static void settle(TeamSimulation sim, long maxMillis) {
        until(sim, () -> sim.invariants().settled(), maxMillis, "the best configuration");
    }

    private static Optional<MissionState> state(TeamSimulation sim, String commander) {
        return sim.cell(commander).missionState();
    }

    @Test
    void theTeamStartsAtTheMinimalConfigurationAndGrowsAsVehiclesJoin() {
        TeamSimulation sim = sim(2, SimVehicle.reconnaissance(2, 1, 0, 0));
        sim.start();
        until(sim, () -> state(sim, "cdr").equals(Optional.of(MissionState.RUNNING)), 10_000, "the minimal configuration");
        settle(sim, 5_000);
        for (String s : List.of("s1", "s2")) {
            Set<String> roles = new HashSet<>();
            sim.cell(s).seats().forEach(seat -> roles.add(seat.role()));
            assertEquals(Set.of("surveyor", "hdetector", "relay"), roles, s + " carries the secondary roles (Fig. 1)");
        }
        for (SimVehicle v : List.of(SimVehicle.detector("d1"), SimVehicle.detector("d2"), SimVehicle.relay("r1"),
                SimVehicle.relay("r2"))) {
            sim.join(v);
        }
        until(sim, () -> state(sim, "cdr").equals(Optional.of(MissionState.OPTIMAL)), 10_000, "the optimal configuration");
        settle(sim, 1_000);
        for (String s : List.of("s1", "s2")) {
            assertEquals(1, sim.cell(s).seats().size(), s + " gave its secondary roles to vehicles of their own (Fig. 2)");
            assertEquals(2, sim.cell(s).children().size());
        }
    }

    @Test
    void identitiesAreDistinctAndFollowTheTreeLevels() {
        TeamSimulation sim = sim(3, SimVehicle.reconnaissance(2, 1, 2, 2));
        sim.start();
        settle(sim, 15_000);
        Set<Identity> seen = new HashSet<>();
        for (Cell c : sim.cells()) {
            Identity id = c.identity().orElseThrow(() -> new AssertionError(c.view().toJson()));
            assertTrue(seen.add(id), "identity " + id + " appears twice");
            int expected = c.isActingCommander() ? 0 : c.seats().get(0).role().equals("surveyor")
                    || c.seats().get(0).role().equals("aggregator") ? 1 : 2;
            assertEquals(expected, id.level(), c.vehicle() + " " + id);
        }
    }

    @Test
    void aFailedSurveyorIsReplacedByAFreeVehicleWhichReceivesItsLastPosition() {
        List<SimVehicle> team = new ArrayList<>(SimVehicle.reconnaissance(2, 1, 2, 2));
        TeamSimulation sim = sim(4, team);
        sim.start();
        settle(sim, 15_000);
        sim.join(SimVehicle.surveyor("s3"));
        sim.cell("s1").reportState(List.of(new BigDecimal("12.5"), new BigDecimal("-3")));
        sim.run(2_000);
        sim.crash("s1");
        long crashed = sim.nowMillis();
        until(sim, () -> sim.cell("s3").seats().stream().anyMatch(s -> s.role().equals("surveyor")), 3 * FAILURE,
                "s3 taking the surveyor role");
        assertTrue(sim.nowMillis() - crashed <= FAILURE + 1_500, "replaced " + (sim.nowMillis() - crashed) + " ms after the crash");
        assertEquals(List.of(new BigDecimal("12.5"), new BigDecimal("-3")), sim.cell("s3").handedOver());
        until(sim, () -> sim.cell("s3").children().size() == 2 && sim.invariants().settled(), 4 * FAILURE,
                "the orphaned detector and relay re-attached to the new surveyor");
    }

    @Test
    void withNoFreeVehicleTheAggregatorIsMovedToSurveyAsInTheDemonstration() {
        SimVehicle hybrid = new SimVehicle("x", Set.of("motion", "video", "communication"), Set.of("Explorer", "Aggregator"),
                false, false);
        TeamSimulation sim = sim(5, SimVehicle.reconnaissance(2, 0, 0, 0));
        sim.start();
        until(sim, () -> sim.cell("cdr").children().size() == 2, 10_000, "two surveyors");
        sim.join(hybrid);
        until(sim, () -> sim.cell("x").seats().stream().anyMatch(s -> s.role().equals("aggregator")), 10_000,
                "x aggregating");
        sim.cell("s1").reportState(List.of("hazard", new BigDecimal(4), new BigDecimal(7)));
        sim.run(2_000);
        sim.crash("s1");
        until(sim, () -> sim.cell("x").seats().stream().anyMatch(s -> s.role().equals("surveyor")), 3 * FAILURE,
                "x moved to the surveyor role");
        assertFalse(sim.cell("x").seats().stream().anyMatch(s -> s.role().equals("aggregator")));
        assertEquals(List.of("hazard", new BigDecimal(4), new BigDecimal(7)), sim.cell("x").handedOver());
        settle(sim, 4 * FAILURE);
    }

    @Test
    void aBackupCommanderTakesOverAndTheTeamStaysWhole() {
        TeamSimulation sim = sim(6, SimVehicle.reconnaissance(2, 1, 2, 2));
        sim.start();
        settle(sim, 15_000);
        sim.run(3_000);
        Map<String, List<Seat>> before = new java.util.TreeMap<>();
        sim.cells().forEach(c -> before.put(c.vehicle(), c.seats()));
        sim.crash("cdr");
        long crashed = sim.nowMillis();
        until(sim, () -> sim.commanders().size() == 1, 3 * FAILURE, "a new acting commander");
        Cell next = sim.commanders().get(0);
        assertTrue(sim.nowMillis() - crashed <= FAILURE + 4 * 500 + 500, "took over after " + (sim.nowMillis() - crashed) + " ms");
        assertEquals(1, next.epoch());
        settle(sim, 6 * FAILURE);
        for (Cell c : sim.cells()) {
            if (c != next && !before.get(c.vehicle()).isEmpty() && before.get(next.vehicle()).stream()
                    .noneMatch(s -> c.parent().isPresent())) {
                continue;
            }
        }
        long kept = sim.cells().stream().filter(c -> c != next && c.seats().equals(before.get(c.vehicle()))).count();
        assertTrue(kept >= 4, "most vehicles kept their seats through the take-over: " + kept);
    }

    @Test
    void partitionedPartsKeepWorkingAndMergeIntoOneTree() {
        TeamSimulation sim = sim(7, SimVehicle.reconnaissance(3, 2, 2, 2));
        sim.start();
        settle(sim, 15_000);
        sim.run(3_000);
        String backup = sim.cells().stream().filter(c -> !c.isActingCommander() && c.parent().equals(Optional.of("cdr"))
                && c.seats().get(0).role().equals("surveyor")).map(Cell::vehicle).findFirst().orElseThrow();
        List<String> side = new ArrayList<>(List.of(backup, "a2", "s3"));
        sim.cells().stream().filter(c -> c.parent().equals(Optional.of(backup))).forEach(c -> side.add(c.vehicle()));
        sim.partition(side);
        until(sim, () -> sim.commanders().size() == 2, 4 * FAILURE, "a commander in each part");
        sim.run(4 * FAILURE);
        sim.heal();
        until(sim, () -> sim.commanders().size() == 1 && sim.invariants().settled(), 8 * FAILURE, "one merged team");
        for (Cell c : sim.cells()) {
            assertTrue(c.isActingCommander() || c.parent().isPresent() || c.seats().isEmpty(), c.vehicle() + " hangs loose");
        }
    }

    @Test
    void theCentralisedSchemeFormsAFlatTree() {
        TeamSimulation sim = sim(Missions.centralised(), 8, SimVehicle.reconnaissance(2, 1, 2, 2),
                TeamSimulation.Security.IDEAL);
        sim.start();
        until(sim, () -> state(sim, "cdr").equals(Optional.of(MissionState.OPTIMAL)), 15_000, "the optimal configuration");
        settle(sim, 1_000);
        assertEquals(7, sim.cell("cdr").children().size(), "every vehicle is the commander's child");
        for (Cell c : sim.cells()) {
            assertTrue(c.children().isEmpty() || c.isActingCommander(), c.vehicle() + " manages others");
        }
    }

    @Test
    void theCentralisedCommanderHostsSecondaryRolesOnSurveyors() {
        TeamSimulation sim = sim(Missions.centralised(), 9, SimVehicle.reconnaissance(2, 1, 0, 0),
                TeamSimulation.Security.IDEAL);
        sim.start();
        until(sim, () -> state(sim, "cdr").equals(Optional.of(MissionState.RUNNING)), 15_000, "the minimal configuration");
        settle(sim, 2_000);
        assertEquals(3, sim.cell("s1").seats().size(), "s1 holds " + sim.cell("s1").seats());
    }

    @Test
    void aRogueVehicleGetsNothingAndChangesNothing() {
        List<SimVehicle> team = new ArrayList<>(SimVehicle.reconnaissance(2, 1, 2, 2));
        team.add(SimVehicle.surveyor("rogue").asRogue());
        team.add(SimVehicle.command("boss").asCommander().asRogue());
        TeamSimulation sim = sim(10, team);
        sim.start();
        settle(sim, 15_000);
        sim.run(10_000);
        assertTrue(sim.cell("rogue").seats().isEmpty());
        assertTrue(sim.cell("boss").children().isEmpty(), "nobody joined the rogue commander");
    }

    @Test
    void aVehicleLeavesGracefullyAndRejoins() {
        TeamSimulation sim = sim(11, SimVehicle.reconnaissance(2, 1, 2, 2));
        sim.start();
        settle(sim, 15_000);
        sim.leave("d1");
        until(sim, () -> sim.cells().stream().noneMatch(c -> c.children().containsKey("d1")), 1_000, "d1 gone from its parent");
        settle(sim, 5_000);
        sim.rejoin("d1");
        until(sim, () -> !sim.cell("d1").seats().isEmpty(), 5_000, "d1 back in the team");
        settle(sim, 5_000);
    }

    @Test
    void aRestartedVehicleJoinsAgain() {
        TeamSimulation sim = sim(12, SimVehicle.reconnaissance(2, 1, 2, 2));
        sim.start();
        settle(sim, 15_000);
        sim.crash("r2");
        sim.run(500);
        sim.restart("r2");
        settle(sim, 4 * FAILURE);
        assertFalse(sim.cell("r2").seats().isEmpty(), () -> sim.invariants().unsettled() + "\n"
                + String.join("\n", sim.trace()));
    }

    @Test
    void realCryptographyFormsTheSameTeam() {
        TeamSimulation sim = sim(Missions.reconnaissance(), 13, SimVehicle.reconnaissance(2, 1, 2, 2),
                TeamSimulation.Security.REAL);
        sim.start();
        until(sim, () -> state(sim, "cdr").equals(Optional.of(MissionState.OPTIMAL)), 20_000, "the optimal configuration");
        settle(sim, 1_000);
    }

    @Test
    void theSameSeedReplaysTheSameRun() {
        List<List<String>> traces = new ArrayList<>();
        for (int i = 0; i < 2; i++) {
            TeamSimulation sim = sim(14, SimVehicle.reconnaissance(2, 1, 2, 2));
            sim.link(net.smc.sim.team.TeamInvariants.lossy(0.2));
            sim.start();
            sim.run(8_000);
            sim.crash("s1");
            sim.run(8_000);
            traces.add(sim.trace());
        }
        assertEquals(traces.get(0), traces.get(1));
    }

    @Test
    void thePoliciesDecide_withTableIDeactivatedNoSurveyorIsAssigned() {
        TeamSimulation sim = sim(15, SimVehicle.reconnaissance(2, 1, 0, 0));
        sim.start();
        sim.cell("cdr").engine().run("test", "root/role/commander/policy/assignSurveyor active: false.");
        sim.run(10_000);
        assertTrue(sim.cells().stream().noneMatch(c -> c.seats().stream().anyMatch(s -> s.role().equals("surveyor"))),
                "a surveyor was assigned although the role-assignment policy is inactive");
        assertTrue(sim.cell("a1").seats().stream().anyMatch(s -> s.role().equals("aggregator")),
                "the aggregator policy still assigns");
        sim.cell("cdr").engine().run("test", "root/role/commander/policy/assignSurveyor active: true.");
        until(sim, () -> state(sim, "cdr").equals(Optional.of(MissionState.RUNNING)), 10_000, "the minimal configuration");
    }

    @Test
    void thePoliciesDecide_whileRecruitingIsHeldTheCommanderDiscoversNoOne() {
        TeamSimulation sim = sim(17, SimVehicle.reconnaissance(2, 1, 0, 0));
        sim.start();
        sim.cell("cdr").engine().run("test", "root/discovery hold.");
        sim.run(10_000);
        assertTrue(sim.cell("cdr").children().isEmpty(), () -> "children while held: " + sim.cell("cdr").children());
        assertTrue(sim.trace().stream().noneMatch(l -> l.contains("DISCOVERING")), () -> String.join("\n", sim.trace()));
        assertTrue(sim.cells().stream().allMatch(c -> c.isActingCommander() || c.seats().isEmpty()));
        sim.cell("cdr").engine().run("test", "root/discovery resume.");
        until(sim, () -> state(sim, "cdr").equals(Optional.of(MissionState.RUNNING)), 10_000, "the minimal configuration");
    }

    @Test
    void aTeamOfTwoHundredCellsFormsAndRecoversFromACrash() {
        List<SimVehicle> team = new ArrayList<>(SimVehicle.reconnaissance(40, 40, 60, 59));
        TeamSimulation sim = sim(16, team);
        sim.start();
        until(sim, () -> state(sim, "cdr").equals(Optional.of(MissionState.OPTIMAL)), 20_000, "the optimal configuration");
        settle(sim, 5_000);
        assertEquals(200, sim.cells().size());
        String surveyor = sim.cell("cdr").children().entrySet().stream()
                .filter(e -> e.getValue().get(0).role().equals("surveyor")).map(Map.Entry::getKey).findFirst().orElseThrow();
        sim.crash(surveyor);
        until(sim, () -> sim.cell("cdr").children().values().stream().filter(v -> v.get(0).role().equals("surveyor"))
                .count() == 2 && sim.invariants().settled(), 4 * FAILURE, "a new surveyor");
    }
}
