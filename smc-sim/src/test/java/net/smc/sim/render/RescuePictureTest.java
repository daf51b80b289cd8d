package net.smc.sim.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Color;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import javax.imageio.ImageIO;

import net.smc.sim.arena.Arena;
import net.smc.sim.world.Worlds;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/** Drives the Fig. 7 run and writes its picture, film and timeline to smc-sim/build/render/. */
class RescuePictureTest {
    private static RescueRun run;
    private static Path out;

    @BeforeAll
    static void drive() throws IOException {
        run = new RescueRun(GifRecorder.Settings.defaults());
        run.run(120_000);
        out = Worlds.projectDir().resolve("smc-sim/build/render");
        Files.createDirectories(out);
        ImageIO.write(new WorldPainter().render(run.world, run.scene, 1200, 860), "png", out.resolve("rescue.png").toFile());
        run.gif.write(out.resolve("rescue.gif"));
        run.timeline.writeCsv(out.resolve("rescue-timeline.csv"));
    }

    @Test
    void firstSurveyor_isStoppedByTheHazard_andTheSecondReachesTheSoldier() {
        assertTrue(run.r1.disabled(), "r1 should be disabled");
        assertEquals("hazard:h1", run.r1.disabledBy());
        assertTrue(run.reached, "r2 should reach the soldier; it is at " + run.r2.pose());
        assertTrue(run.r2.pose().distanceTo(RescueRun.SOLDIER_X, RescueRun.SOLDIER_Y) < 0.8);
    }

    @Test
    void png_isWrittenAtTheAskedSize() throws IOException {
        BufferedImage png = ImageIO.read(out.resolve("rescue.png").toFile());
        assertEquals(1200, png.getWidth());
        assertEquals(860, png.getHeight());
    }

    @Test
    void png_showsTheHazardTheStopAndTheSecondSurveyorsPath() throws IOException {
        BufferedImage png = ImageIO.read(out.resolve("rescue.png").toFile());
        Viewport v = Viewport.fit(run.world.arena(), 1200, 860);
        Arena.Hazard hazard = run.world.arena().hazard("h1").orElseThrow();
        assertNear(Palette.HAZARD, Pixels.at(png, v, hazard.x(), hazard.y()), "hazard centre");
        assertNear(Palette.MARK, Pixels.at(png, v, run.r1.x(), run.r1.y()), "the X where r1 stopped");
        assertNear(Palette.robot(1), Pixels.at(png, v, run.r2.x(), run.r2.y()), "r2 at the soldier");
        List<TrajectoryRecorder.Point> path = run.tracks.path("r2");
        TrajectoryRecorder.Point middle = path.get(path.size() / 2);
        assertTrue(middle.y() < hazard.y() - 1.5, "r2 went round, south of the hazard: " + middle);
        assertNear(Palette.robot(1), Pixels.at(png, v, middle.x(), middle.y()), "r2's path at " + middle);
    }

    @Test
    void gif_ofTheRunIsSmall_andHasManyFrames() throws IOException {
        assertTrue(run.gif.frames() >= 20, run.gif.frames() + " frames");
        assertTrue(Files.size(out.resolve("rescue.gif")) < 4_000_000, Files.size(out.resolve("rescue.gif")) + " bytes");
    }

    private static void assertNear(Color expected, Color actual, String what) {
        assertTrue(Pixels.near(expected, actual, 12), what + ": expected " + Pixels.hex(expected) + ", got " + Pixels.hex(actual));
    }
}
