package net.smc.sim.scenario;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Color;
import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.ArrayList;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.stream.LongStream;
import java.util.stream.Stream;

import net.smc.sim.render.Overlays;
import net.smc.sim.render.Palette;
import net.smc.sim.render.Pixels;
import net.smc.sim.render.Timeline;
import net.smc.sim.render.Viewport;
import net.smc.sim.render.WorldPainter;
import net.smc.sim.robot.SimRobot;
import net.smc.sim.team.TeamSimulation;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestFactory;

/**
 * The reconnaissance of section II-A in the house: one run of 260 s of mission time (seed 1)
 * passes through the minimal and the reasonably-optimal configurations, contracts when a
 * detector's battery dies and grows again when the spare enters, names every change on the
 * timeline, and its hazard map shows what it claims. The mission's goal (90% of the free floor
 * and every hazard on the map within the 900 s limit) is checked on full missions of seeds 1 to
 * {@value #SEEDS} in every run, a few at a time on a small pool of threads (a run ends when the
 * goal is met: some 2 to 4 s of CPU per seed); {@code -Ptest.smc.recon.seeds=N},
 * {@code -Ptest.smc.recon.firstSeed=F} and {@code -Ptest.smc.recon.threads=T} run seeds F to F + N - 1
 * on T threads (seeds 1 to 50: about 110 s of CPU in all, so about a minute of wall time on two threads).
 */
class ReconnaissanceScenarioTest {
    private static final Path PROJECT = Path.of(System.getProperty("smc.project.dir", ".."));
    private static final long SHORT_RUN = 260_000;
    /**
     * Seeds 1 to this are run to the goal in every test run (about 2 minutes of wall time on two
     * threads). The goal is met on all of them, not on every seed beyond them (see the README:
     * 48 of 50 of seeds 51 to 100 and of 101 to 150).
     */
    static final int SEEDS = 50;
    /** The longest wait for one seed's outcome, minutes of wall time. */
    private static final long SEED_TIMEOUT_MINUTES = 10;

    private static ReconnaissanceScenario run;
    private static ReconnaissanceOutcome outcome;

    @BeforeAll
    static void shortRun() throws Exception {
        run = ReconnaissanceScenario.load(PROJECT, ReconnaissanceSettings.of(1).withLimit(SHORT_RUN), row -> { });
        outcome = run.run();
    }

    private static String timeline() {
        return String.join("\n", run.timeline().rows().stream().map(ScenarioLog::format).toList());
    }

    private static List<Timeline.Row> rows(String what) {
        return run.timeline().rows().stream().filter(r -> r.what().equals(what)).toList();
    }

    @Test
    void theTeamGrowsFromTheMinimalToTheOptimalConfiguration_contractsOnTheFailure_andGrowsAgain() {
        List<String> standings = outcome.standings();
        int minimal = standings.indexOf("minimal");
        int optimal = standings.indexOf("optimal");
        assertTrue(minimal >= 0 && optimal > minimal, "minimal, then optimal: " + standings);
        long failure = run.settings().failureMillis();
        List<Timeline.Row> after = rows("CONFIGURATION").stream().filter(r -> r.timeMillis() > failure).toList();
        assertTrue(after.stream().anyMatch(r -> r.detail().startsWith("grown:") && r.detail().contains("surveyor+hdetector")),
                "after the failure a surveyor holds the failed detector's seat again (contraction):\n" + timeline());
        assertTrue(after.stream().anyMatch(r -> r.detail().startsWith("optimal:") && r.detail().contains("s3 hdetector")),
                "the spare takes the seat and the team is optimal again:\n" + timeline());
        List<String> states = rows("MISSION_STATE").stream().map(r -> r.detail().split(" ")[0]).toList();
        int firstOptimal = states.indexOf("OPTIMAL");
        assertTrue(firstOptimal >= 0 && states.subList(firstOptimal, states.size()).contains("RUNNING"),
                "the commander's state goes back from OPTIMAL to RUNNING: " + states);
    }

    @Test
    void everyConfigurationChangeIsNamedOnce() {
        List<Timeline.Row> configurations = rows("CONFIGURATION");
        assertTrue(configurations.size() >= 10, "the team changed often as robots entered: " + configurations.size());
        for (int i = 1; i < configurations.size(); i++) {
            assertFalse(configurations.get(i).detail().equals(configurations.get(i - 1).detail()),
                    "row " + i + " repeats the configuration before it: " + configurations.get(i).detail());
        }
        assertTrue(configurations.stream().anyMatch(r -> r.detail().startsWith("minimal: ")
                && r.detail().contains("s1 surveyor+hdetector+relay") && r.detail().contains("s2 surveyor+hdetector+relay")),
                "Fig. 1 is named minimal, with each surveyor holding the relay and detector seats too:\n" + timeline());
        assertTrue(configurations.stream().anyMatch(r -> r.detail().startsWith("optimal: ") && r.detail().contains("d1 hdetector")
                && r.detail().contains("r1 relay") && r.detail().contains("s1 surveyor,")),
                "Fig. 2 is named optimal:\n" + timeline());
        long entered = rows("ENTERED").size();
        assertEquals(run.schedule().size(), entered, "every robot entered");
        assertTrue(rows("STOPPED").stream().anyMatch(r -> r.vehicle().equals(run.failingRobot()) && r.detail().contains("battery")),
                "the failure is on the timeline");
    }

    @Test
    void theHazardMapShowsTheReportedHazards_theRobots_andWhatIsNotMapped() {
        // Without the legend, which covers the north-east room, where a robot may stand.
        BufferedImage image = new WorldPainter().render(run.world(),
                run.hazardMapScene().overlays(Overlays.defaults().withLegend(false)), 1200, 860);
        assertEquals(1200, image.getWidth());
        assertEquals(860, image.getHeight());
        Viewport v = Viewport.fit(run.world().arena(), 1200, 860);
        List<Object[]> reported = new ArrayList<>();
        run.hazardMapScene().marks().forEach(m -> {
            if (m instanceof net.smc.sim.render.Mark.Found f) {
                reported.add(new Object[] {f.x(), f.y()});
            }
        });
        assertEquals(run.hazardMap().isPresent() ? reported.size() : 0, reported.size());
        assertTrue(reported.size() >= outcome.hazardsFound().size(), "a diamond for every hazard found");
        for (Object[] p : reported) {
            // Within 3 pixels of its centre (the diamond reaches 6 or more).
            Color c = Pixels.at(image, v, (double) p[0], (double) p[1]);
            assertTrue(Pixels.nearby(image, v, (double) p[0], (double) p[1], 3, Palette.FOUND, 12),
                    "a found hazard's diamond at " + p[0] + "," + p[1] + ": " + Pixels.hex(c) + " at its centre");
        }
        List<SimRobot> robots = run.world().robots();
        int checked = 0;
        for (int i = 0; i < robots.size(); i++) {
            SimRobot r = robots.get(i);
            Color c = Pixels.at(image, v, r.x(), r.y());
            boolean crowded = robots.stream().anyMatch(o -> o != r && Math.hypot(o.x() - r.x(), o.y() - r.y()) < 1.0);
            var map = run.hazardMap().orElseThrow();
            boolean shaded = !map.isKnown(map.col(r.x()), map.row(r.y()));   // a surveyor at the edge of what is mapped
            // a detector stands where it confirmed a hazard, and the hazard's diamond is drawn there
            boolean underDiamond = reported.stream().anyMatch(p -> Math.hypot((double) p[0] - r.x(), (double) p[1] - r.y()) < 0.6);
            Color expected = r.disabled() || crowded || shaded || underDiamond ? null : Palette.robot(i);   // another's body or label may cover it
            if (expected != null) {
                checked++;
                assertTrue(Pixels.near(expected, c, 12), "robot " + r.id() + " in its colour: " + Pixels.hex(c));
            }
        }
        assertTrue(checked >= 3, "robots standing apart, checked in their colours: " + checked);
        OccupancyGridCells unknown = OccupancyGridCells.firstUnknownFloor(run);
        if (unknown != null) {
            Color c = Pixels.at(image, v, unknown.x(), unknown.y());
            assertTrue(c.getRed() < Palette.FLOOR.getRed() - 40, "floor not on the map is shaded at " + unknown + ": " + Pixels.hex(c));
        }
    }

    /** A free-floor cell the hazard map does not know, by its centre. */
    private record OccupancyGridCells(double x, double y) {
        static OccupancyGridCells firstUnknownFloor(ReconnaissanceScenario s) {
            var map = s.hazardMap().orElseThrow();
            for (int r = 0; r < map.rows(); r++) {
                for (int c = 0; c < map.cols(); c++) {
                    if (s.floor().isFloor(c, r) && !map.isKnown(c, r)) {
                        var p = map.centre(c, r);
                        boolean nearRobot = s.world().robots().stream().anyMatch(b -> Math.hypot(b.x() - p.x(), b.y() - p.y()) < 0.8);
                        if (!nearRobot) {
                            return new OccupancyGridCells(p.x(), p.y());
                        }
                    }
                }
            }
            return null;
        }
    }

    /**
     * The goal on full missions of seeds {@code smc.recon.firstSeed} (1) to that plus
     * {@code smc.recon.seeds} ({@value #SEEDS}) less one, run on {@code smc.recon.threads} threads (the
     * processors, at most 4): each run has its own team, world and scheduler and shares nothing
     * mutable with the others (the processes' caches of parses and verified credentials are
     * thread-safe and change no outcome), so a seed ends the same whatever the threads. One test per
     * seed, its failure naming the seed, the floor mapped and the hazards missing.
     */
    @TestFactory
    Stream<DynamicTest> theGoalIsMetOnEverySeed() {
        long first = Long.getLong("smc.recon.firstSeed", 1);
        int count = Integer.getInteger("smc.recon.seeds", SEEDS);
        int threads = Integer.getInteger("smc.recon.threads", Math.min(4, Runtime.getRuntime().availableProcessors()));
        if (count < 1 || threads < 1) {
            throw new IllegalArgumentException("smc.recon.seeds " + count + " and smc.recon.threads " + threads
                    + " must both be 1 or more");
        }
        ExecutorService pool = Executors.newFixedThreadPool(threads, task -> {
            Thread t = new Thread(task, "reconnaissance seed");
            t.setDaemon(true);
            return t;
        });
        List<Long> seeds = LongStream.range(first, first + count).boxed().toList();
        List<Future<SeedRun>> runs = seeds.stream().map(seed -> pool.submit(() -> SeedRun.of(seed))).toList();
        pool.shutdown();
        return seeds.stream().map(seed -> DynamicTest.dynamicTest("seed " + seed, () -> {
            SeedRun r;
            try {
                r = runs.get(seeds.indexOf(seed)).get(SEED_TIMEOUT_MINUTES, TimeUnit.MINUTES);
            } catch (ExecutionException e) {
                throw new AssertionError("seed " + seed + ": the run failed: " + e.getCause(), e.getCause());
            } catch (TimeoutException e) {
                throw new AssertionError("seed " + seed + ": no outcome within " + SEED_TIMEOUT_MINUTES + " minutes of wall time");
            }
            System.out.println(r.measured());
            assertTrue(r.outcome().succeeded() && r.outcome().coverage() >= 0.9 && r.missing().isEmpty(), r::failure);
        }));
    }

    /** One seed's full mission: its outcome, the hazards it did not find and the CPU time of its thread. */
    private record SeedRun(long seed, ReconnaissanceOutcome outcome, List<String> missing, double cpuSeconds) {
        static SeedRun of(long seed) throws Exception {
            ThreadMXBean threads = ManagementFactory.getThreadMXBean();
            long cpu = threads.getCurrentThreadCpuTime();
            ReconnaissanceScenario s = ReconnaissanceScenario.load(PROJECT, ReconnaissanceSettings.of(seed)
                    .withSecurity(TeamSimulation.Security.IDEAL), row -> { });
            ReconnaissanceOutcome o = s.run();
            List<String> missing = s.world().arena().hazards().stream().map(h -> h.id())
                    .filter(id -> !o.hazardsFound().contains(id)).toList();
            return new SeedRun(seed, o, missing, (threads.getCurrentThreadCpuTime() - cpu) / 1e9);
        }

        String failure() {
            return String.format(Locale.ROOT, "seed %d: %s; %.1f%% of the free floor (goal 90%%), hazards missing %s",
                    seed, outcome.reason(), outcome.coverage() * 100, missing);
        }

        String measured() {
            return String.format(Locale.ROOT, "measured: reconnaissance seed %d: 90%% of the free floor at %d ms, goal %s at %d ms,"
                    + " %.1f s of CPU", seed, outcome.coverageMillis(), outcome.succeeded() ? "met" : "not met",
                    outcome.missionMillis(), cpuSeconds);
        }
    }
}
