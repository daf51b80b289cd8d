package net.smc.demo;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.util.Locale;


import net.smc.core.mission.MissionException;
import net.smc.sim.arena.ArenaException;
import net.smc.sim.render.GifRecorder;
import net.smc.sim.render.NoDisplayException;
import net.smc.sim.render.Overlays;
import net.smc.sim.render.PacedLoop;
import net.smc.sim.render.Timeline;
import net.smc.sim.render.ViewControls;
import net.smc.sim.render.WorldPainter;
import net.smc.sim.render.WorldWindow;
import net.smc.sim.scenario.ReconnaissanceOutcome;
import net.smc.sim.scenario.ReconnaissanceScenario;
import net.smc.sim.scenario.ReconnaissanceSettings;
import net.smc.sim.scenario.RescueScenario;
import net.smc.sim.team.TeamSimulation;

/**
 * {@code smc demo reconnaissance}: the reconnaissance of section II-A in the simulated house,
 * its timeline printed as it happens, and into DIR the hazard map {@code reconnaissance-map.png},
 * the film {@code reconnaissance.gif} and {@code reconnaissance-timeline.csv}. Exit 0 when the
 * hazard map covers the goal's share of the free floor and holds every hazard, 1 with the reason
 * when not. The options were checked by {@link DemoCommand}.
 */
final class ReconnaissanceDemo {
    /** Picture size, pixels. */
    private static final int WIDTH = 1200;
    private static final int HEIGHT = 860;
    /** A frame every 10 s of mission time (500 steps of 20 ms), at most 100 frames: each frame costs a render and its colours. */
    private static final GifRecorder.Settings FILM = new GifRecorder.Settings(500, 100, 560, 120);

    private final Io io;

    ReconnaissanceDemo(Io io) {
        this.io = io;
    }

    /**
     * Runs it.
     *
     * @param limitMillis the mission time after which it gives up, or a negative number for the scenario's own
     */
    int run(long seed, double loss, long limitMillis, boolean gui, double speed, Path dir) throws IOException, InterruptedException,
            MissionException, ArenaException {
        ReconnaissanceSettings settings = ReconnaissanceSettings.of(seed).withLoss(loss)
                .withSecurity(TeamSimulation.Security.REAL).withFilm(FILM);
        if (limitMillis > 0) {
            settings = settings.withLimit(limitMillis);
        }
        io.stdout().println("reconnaissance of the house (section II-A), seed " + seed + ", loss " + loss
                + ", signed traffic over the world's radio");
        ReconnaissanceScenario recon = ReconnaissanceScenario.load(io.workingDir(), settings, this::print);
        long wall = System.nanoTime();
        recon.start();
        if (gui) {
            showWhileRunning(recon, speed);
        }
        recon.advance(Long.MAX_VALUE);
        ReconnaissanceOutcome outcome = recon.finish();
        double wallSeconds = (System.nanoTime() - wall) / 1e9;
        BufferedImage map = new WorldPainter().render(recon.world(), recon.hazardMapScene(), WIDTH, HEIGHT);
        DemoCommand.writePng(map, dir.resolve("reconnaissance-map.png"));
        recon.film().orElseThrow().write(dir.resolve("reconnaissance.gif"));
        recon.timeline().writeCsv(dir.resolve("reconnaissance-timeline.csv"));
        io.stdout().println(String.format(Locale.ROOT, "%.1f s of mission time in %.1f s (%.1fx real time); files in %s",
                outcome.missionMillis() / 1000.0, wallSeconds, outcome.missionMillis() / 1000.0 / wallSeconds, dir));
        if (outcome.coverageMillis() >= 0) {
            io.stdout().println(String.format(Locale.ROOT, "%.0f%% of the free floor mapped at %.1f s",
                    recon.settings().coverageGoal() * 100, outcome.coverageMillis() / 1000.0));
        }
        io.stdout().println("configurations: " + String.join(" -> ", outcome.standings()));
        recon.diagnostics().forEach((vehicle, errors) -> errors.forEach(e -> io.stderr().println(vehicle + ": " + e)));
        if (outcome.succeeded()) {
            io.stdout().println("succeeded: " + outcome.reason());
            return 0;
        }
        io.stdout().println("failed: " + outcome.reason());
        return 1;
    }

    private void print(Timeline.Row row) {
        io.stdout().println(RescueScenario.format(row));
    }

    private void showWhileRunning(ReconnaissanceScenario recon, double speed) throws InterruptedException {
        ViewControls controls = new ViewControls(speed, Overlays.defaults());
        try (WorldWindow window = WorldWindow.open("smc demo reconnaissance", WIDTH, HEIGHT, controls)) {
            PacedLoop.realTime(window.controls(), 40).run(recon::advance, () -> window.show(recon.world(), recon.scene()),
                    () -> window.closed() || recon.finished());
        } catch (NoDisplayException e) {
            io.stdout().println(e.getMessage());
        }
    }
}
