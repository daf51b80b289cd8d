package net.smc.sim.experiment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;

import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

import net.smc.core.cell.Scheme;
import net.smc.core.mission.Mission;
import net.smc.core.mission.MissionLoader;
import net.smc.policy.api.PolicyRepository;

class SetupTimeRunTest {
    /** Fixed costs of the order Calibration measures, so the test does not depend on the machine. */
    static final CpuCosts COSTS = new CpuCosts(60_000, 120_000, 90_000, 800, 4, 600, 3, 3_000, 500);

    @TempDir
    Path dir;

    @ParameterizedTest(name = "{0} roles, {1}")
    @CsvSource({"5, DISTRIBUTED", "5, CENTRALISED", "20, DISTRIBUTED", "20, CENTRALISED"})
    void everyRoleStarts(int roles, Scheme scheme) throws Exception {
        GeneratedMission g = MissionGenerator.write(TreeShape.of(roles, 4), dir, Project.bootEvents());
        Mission mission = new MissionLoader(new PolicyRepository(g.repository())).load(g.instanceFile(scheme));
        for (int run = 1; run <= 2; run++) {
            SetupResult r = SetupTimeRun.run(g, mission, scheme, run, 40 + run, RadioNetwork.ADHOC_80211, COSTS, 60_000);
            assertTrue(r.complete(), () -> "not every role started: " + r);
            assertEquals(roles - 1, r.started());
            assertTrue(r.setupMillis() > 0 && r.messages() > 0 && r.bytes() > 0 && r.busiestCpuMillis() > 0, r::toString);
        }
    }
}
