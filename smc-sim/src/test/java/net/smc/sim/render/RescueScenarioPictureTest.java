package net.smc.sim.render;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Color;
import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.List;

import net.smc.sim.robot.SimRobot;
import net.smc.sim.scenario.RescueScenario;
import net.smc.sim.team.TeamSimulation;
import net.smc.sim.world.Arena;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/** The picture of the rescue run by cells and policies shows what it claims (cf. Fig. 7). */
class RescueScenarioPictureTest {
    private static RescueScenario rescue;
    private static RescueScenario.Outcome outcome;
    private static BufferedImage png;
    private static Viewport view;

    @BeforeAll
    static void run() throws Exception {
        rescue = RescueScenario.load(Path.of(System.getProperty("smc.project.dir", "..")),
                RescueScenario.Settings.of(5).withSecurity(TeamSimulation.Security.IDEAL)
                        .withFilm(GifRecorder.Settings.defaults()), row -> { });
        outcome = rescue.run();
        png = new WorldPainter().render(rescue.world(), rescue.scene(), 1200, 860);
        view = Viewport.fit(rescue.world().arena(), 1200, 860);
        java.nio.file.Path dir = java.nio.file.Path.of(System.getProperty("smc.project.dir", "..")).resolve("smc-sim/build/render");
        java.nio.file.Files.createDirectories(dir);
        javax.imageio.ImageIO.write(png, "png", dir.resolve("rescue-scenario.png").toFile());
    }

    @Test
    void showsTheHazard_andAnXWhereTheFirstSurveyorStopped() {
        assertTrue(outcome.succeeded(), outcome.reason());
        Arena.Hazard hazard = rescue.hazard();
        // A robot's role label may cover part of the cylinder: some point of it shows.
        double r = hazard.radius() * 0.6;
        double[][] points = {{0, 0}, {r, 0}, {-r, 0}, {0, r}, {0, -r}};
        boolean seen = false;
        for (double[] d : points) {
            seen |= Pixels.near(Palette.HAZARD, Pixels.at(png, view, hazard.x() + d[0], hazard.y() + d[1]), 12);
        }
        assertTrue(seen, "the hazard's cylinder is drawn at " + hazard.x() + "," + hazard.y());
        SimRobot first = rescue.world().robot(outcome.firstSurveyor());
        assertTrue(first.disabled(), "the first surveyor is stopped");
        assertNear(Palette.MARK, Pixels.at(png, view, first.x(), first.y()), "the X where it stopped");
    }

    @Test
    void showsTheSecondSurveyorsPath_outsideTheHazard_andTheAvoidedZone() {
        List<TrajectoryRecorder.Point> path = rescue.trajectories().path(outcome.secondSurveyor());
        TrajectoryRecorder.Point middle = path.get(path.size() / 2);
        int index = rescue.world().robots().indexOf(rescue.world().robot(outcome.secondSurveyor()));
        assertNear(Palette.robot(index), Pixels.at(png, view, middle.x(), middle.y()), "its path at " + middle);
        assertTrue(rescue.scene().marks().stream().anyMatch(m -> m instanceof Mark.AvoidedZone z
                && rescue.world().robot(outcome.firstSurveyor()).pose().distanceTo(z.x(), z.y()) < 0.5),
                "the zone about the first surveyor's last position is marked: " + rescue.scene().marks());
    }

    @Test
    void filmHasFrames() {
        GifRecorder film = rescue.film().orElseThrow();
        assertTrue(film.frames() >= 20, film.frames() + " frames");
    }

    private static void assertNear(Color expected, Color actual, String what) {
        assertTrue(Pixels.near(expected, actual, 12), what + ": expected " + Pixels.hex(expected) + ", got " + Pixels.hex(actual));
    }
}
