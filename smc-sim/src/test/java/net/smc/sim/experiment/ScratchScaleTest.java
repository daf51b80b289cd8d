package net.smc.sim.experiment;

import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import net.smc.core.cell.Scheme;
import net.smc.core.mission.Mission;
import net.smc.core.mission.MissionLoader;
import net.smc.policy.PolicyRepository;

class ScratchScaleTest {
    @TempDir Path dir;
    @Test
    void scale() throws Exception {
        GeneratedMission g0 = MissionGenerator.write(TreeShape.of(20, 4), dir.resolve("c"), Project.bootEvents());
        CpuCosts costs = Calibration.measure(Project.bootEvents(), g0);
        System.out.println("COSTS " + costs);
        for (int n : new int[] {10, 100, 1000}) {
            GeneratedMission g = MissionGenerator.write(TreeShape.of(n, 4), dir.resolve("m" + n), Project.bootEvents());
            for (Scheme s : Scheme.values()) {
                Mission m = new MissionLoader(new PolicyRepository(g.repository())).load(g.instanceFile(s));
                long t0 = System.nanoTime();
                SetupResult r = SetupTimeRun.run(g, m, s, 1, 7, RadioNetwork.ADHOC_80211, costs, 120_000);
                System.out.println("RESULT " + r + " wall " + (System.nanoTime() - t0) / 1e9);
            }
        }
    }
}
