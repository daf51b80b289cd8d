package net.smc.sim.scenario;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;

import net.smc.sim.team.TeamSimulation;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** The rescue of section IV-C, decided by the policies, on many seeds. */
class RescueScenarioTest {
    private static final Path PROJECT = Path.of(System.getProperty("smc.project.dir", ".."));

    private static RescueScenario.Outcome run(long seed, double loss) throws Exception {
        RescueScenario s = RescueScenario.load(PROJECT, RescueScenario.Settings.of(seed).withLoss(loss)
                .withSecurity(TeamSimulation.Security.IDEAL), row -> { });
        RescueScenario.Outcome o = s.run();
        assertTrue(o.succeeded(), () -> "seed " + seed + ": " + o.reason() + "\n" + s.timeline().rows());
        assertEquals("r1".equals(o.firstSurveyor()) ? "r2" : "r1", o.secondSurveyor(), "the aggregator takes over");
        assertTrue(o.closestToHazard() > s.hazard().effect(), () -> "seed " + seed + ": the second surveyor came within "
                + o.closestToHazard() + " m of the hazard (effect " + s.hazard().effect() + " m)");
        long comTimeout = 500;
        long failureTimeout = 2000;
        assertTrue(o.firstStopMillis() >= 0 && o.reassignedMillis() > o.firstStopMillis(), "stop, then re-assignment");
        assertTrue(o.reassignedMillis() - o.firstStopMillis() <= failureTimeout + 4 * comTimeout,
                () -> "seed " + seed + ": re-assigned " + (o.reassignedMillis() - o.firstStopMillis()) + " ms after the stop");
        return o;
    }

    @ParameterizedTest
    @ValueSource(longs = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20})
    void rescueSucceeds(long seed) throws Exception {
        run(seed, 0);
    }

    @ParameterizedTest
    @ValueSource(longs = {101, 102, 103, 104, 105})
    void rescueSucceedsWithTenPercentLoss(long seed) throws Exception {
        run(seed, 0.10);
    }
}
