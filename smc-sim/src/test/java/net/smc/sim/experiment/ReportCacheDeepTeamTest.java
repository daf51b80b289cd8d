package net.smc.sim.experiment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.SplittableRandom;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import net.smc.core.cell.ReportChecks;
import net.smc.core.cell.Scheme;
import net.smc.core.mission.Mission;
import net.smc.core.mission.MissionLoader;
import net.smc.policy.api.PolicyRepository;
import net.smc.sim.team.TeamSimulation;

/**
 * A cell keeps the subtree report it sends its parent from tick to tick and builds it again only
 * when something it is built from moved: its seats and children, their own reports, its state, its
 * lease. In a tree four levels deep (40 roles, fan-out 3) a vehicle two levels down crashing and
 * restarting changes the reports all the way up without changing the links of the cells above its
 * parent. With {@link ReportChecks} on, every tick where a cell keeps its report also builds it
 * afresh: no kept report may differ (a change some writer did not record), and many must have been
 * compared.
 */
class ReportCacheDeepTeamTest {
    @TempDir
    Path dir;

    @AfterEach
    void off() {
        ReportChecks.enable(false);
    }

    @Test
    void keptReportsMatchAFreshBuildWhileVehiclesDeepInTheTreeCrashAndRestart() throws Exception {
        GeneratedMission g = MissionGenerator.write(TreeShape.of(40, 4), dir, Project.bootEvents());
        PolicyRepository repository = new PolicyRepository(g.repository());
        Mission mission = new MissionLoader(repository).load(g.instanceFile(Scheme.DISTRIBUTED));
        List<String> deep = g.vehicles().stream().map(v -> v.id()).filter(id -> id.contains("l2") || id.contains("l3")).toList();
        assertTrue(deep.size() >= 30, "vehicles below the second level: " + deep);
        ReportChecks.enable(true);
        for (long seed = 1; seed <= 3; seed++) {
            SplittableRandom random = new SplittableRandom(seed);
            TeamSimulation sim = TeamSimulation.builder(mission, repository, seed).vehicles(g.vehicles()).build();
            sim.start();
            sim.run(8_000);
            for (int i = 0; i < 6; i++) {
                String v = deep.get(random.nextInt(deep.size()));
                sim.crash(v);
                sim.run(3_000 + random.nextInt(2_000));
                sim.restart(v);
                sim.run(4_000 + random.nextInt(2_000));
            }
            assertEquals(0, ReportChecks.stale(), "kept reports that a fresh build contradicts, seed " + seed);
        }
        assertTrue(ReportChecks.agreed() > 10_000, "kept reports compared: " + ReportChecks.agreed());
    }
}
