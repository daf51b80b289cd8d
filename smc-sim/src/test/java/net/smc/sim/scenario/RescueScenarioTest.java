package net.smc.sim.scenario;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.stream.LongStream;

import net.smc.sim.render.Timeline;
import net.smc.sim.team.TeamSimulation;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The rescue of section IV-C, decided by the policies, on many seeds: it succeeds, the aggregator
 * takes over the surveyor role, the second surveyor never enters the hazard's reach, the
 * re-assignment follows the first surveyor's stop within failureTimeout plus a few comTimeouts,
 * and the timeline shows all seven steps. {@code -Ptest.smc.rescue.seeds=N} runs N seeds (default 200).
 */
class RescueScenarioTest {
    private static final Path PROJECT = Path.of(System.getProperty("smc.project.dir", ".."));
    /** missions/rescue.instance.xml. */
    private static final long COM_TIMEOUT = 500;
    private static final long FAILURE_TIMEOUT = 2000;

    static LongStream seeds() {
        return LongStream.rangeClosed(1, Long.getLong("smc.rescue.seeds", 200));
    }

    static LongStream lossySeeds() {
        return LongStream.rangeClosed(1001, 1020);
    }

    private static void check(long seed, double loss) throws Exception {
        RescueScenario s = RescueScenario.load(PROJECT, RescueScenario.Settings.of(seed).withLoss(loss)
                .withSecurity(TeamSimulation.Security.IDEAL), row -> { });
        RescueScenario.Outcome o = s.run();
        String trace = "seed " + seed + ", loss " + loss + ": ";
        assertTrue(o.succeeded(), () -> trace + o.reason() + "\n" + String.join("\n",
                s.timeline().rows().stream().map(RescueScenario::format).toList()));
        assertEquals("r1".equals(o.firstSurveyor()) ? "r2" : "r1", o.secondSurveyor(), trace + "the aggregator takes over");
        double effect = s.hazard().effect();
        assertTrue(o.closestToHazard() > effect, () -> trace + "the second surveyor came within "
                + o.closestToHazard() + " m of the hazard's centre (its reach is " + effect + " m)");
        assertTrue(o.firstStopMillis() >= 0 && o.reassignedMillis() > o.firstStopMillis(), trace + "stop, then re-assignment");
        long lag = o.reassignedMillis() - o.firstStopMillis();
        long bound = FAILURE_TIMEOUT + 4 * COM_TIMEOUT;
        assertTrue(lag <= bound, () -> trace + "re-assigned " + lag + " ms after the stop; bound " + bound + " ms");
        Set<String> steps = new TreeSet<>();
        for (Timeline.Row r : s.timeline().rows()) {
            steps.add(r.step());
        }
        assertTrue(steps.containsAll(List.of("i", "ii", "iii", "iv", "v", "vi", "vii")), trace + "steps on the timeline: " + steps);
    }

    @ParameterizedTest
    @MethodSource("seeds")
    void rescueSucceeds(long seed) throws Exception {
        check(seed, 0);
    }

    @ParameterizedTest
    @MethodSource("lossySeeds")
    void rescueSucceedsWithTenPercentLoss(long seed) throws Exception {
        check(seed, 0.10);
    }
}
