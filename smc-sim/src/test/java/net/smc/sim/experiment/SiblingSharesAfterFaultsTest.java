package net.smc.sim.experiment;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import net.smc.core.cell.Cell;
import net.smc.core.cell.Scheme;
import net.smc.core.mission.Mission;
import net.smc.core.mission.MissionLoader;
import net.smc.policy.api.PolicyRepository;
import net.smc.sim.team.TeamSimulation;

/**
 * Managers with siblings and several seats of a role take their own share of the free vehicles
 * first (ReplyBatches.beginOwnShare): that must hold no seat open for good. At 200 roles (five
 * level-2 managers per branch, about seven leaf seats each), a level-2 manager and three leaves of
 * its branch crash once the team has formed and come back a second later, free: the team forms
 * again, every vehicle holding a seat, the restarted manager vehicle's new role starting with its own
 * share's time again.
 */
class SiblingSharesAfterFaultsTest {
    @TempDir
    Path dir;

    @Test
    void vehiclesThatCrashAndComeBackAreSeatedAgain() throws Exception {
        GeneratedMission g = MissionGenerator.write(TreeShape.of(200, 4), dir, Project.bootEvents());
        Mission mission = new MissionLoader(new PolicyRepository(g.repository())).load(g.instanceFile(Scheme.DISTRIBUTED));
        TeamSimulation sim = TeamSimulation.builder(mission, new PolicyRepository(g.repository()), 7)
                .vehicles(g.vehicles()).scheme(Scheme.DISTRIBUTED).link(RadioNetwork.ADHOC_80211.link()).build();
        sim.start();
        assertTrue(sim.runUntil(() -> allSeated(sim), 10_000), () -> "not formed: " + sim.invariants().unsettled());
        List<String> crashed = List.of("b0l2n0", "b0l3n0", "b0l3n1", "b0l3n2");
        crashed.forEach(sim::crash);
        sim.run(1_000);
        crashed.forEach(sim::restart);
        assertTrue(sim.runUntil(() -> allSeated(sim) && sim.invariants().settled(), 40_000),
                () -> "not formed again: " + sim.invariants().unsettled());
    }

    private static boolean allSeated(TeamSimulation sim) {
        return sim.cells().stream().map(Cell::seats).noneMatch(List::isEmpty);
    }
}
