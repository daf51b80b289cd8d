package net.smc.sim.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;

import javax.imageio.ImageIO;
import javax.imageio.ImageReader;
import javax.imageio.stream.ImageInputStream;

import net.smc.sim.robot.KoalaSpec;
import net.smc.sim.world.SimWorld;
import net.smc.sim.world.Worlds;
import org.junit.jupiter.api.Test;

class GifRecorderTest {

    private static SimWorld movingWorld() {
        SimWorld world = Worlds.world(Worlds.arena(6, 4, "<start id='s0' x='0.5' y='0.5'/>"), 2);
        world.addRobot("a", Worlds.start(1, 2, 0), KoalaSpec.koala()).drive().setWheelSpeeds(0.3, 0.3);
        return world;
    }

    @Test
    void gif_hasSeveralFrames_decodesWithImageIO_andLoops() throws IOException {
        SimWorld world = movingWorld();
        GifRecorder gif = new GifRecorder(new WorldPainter(), new Scene("film"), new GifRecorder.Settings(10, 50, 200, 50));
        world.addListener(gif);
        for (int i = 0; i < 60; i++) {
            world.step();
        }
        assertEquals(6, gif.frames());
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        gif.write(bytes);
        ImageReader reader = ImageIO.getImageReadersByFormatName("gif").next();
        try (ImageInputStream in = ImageIO.createImageInputStream(new ByteArrayInputStream(bytes.toByteArray()))) {
            reader.setInput(in);
            assertEquals(6, reader.getNumImages(true));
            assertEquals(200, reader.read(0).getWidth());
            assertEquals(GifRecorder.height(world, 200), reader.read(5).getHeight());
            Viewport v = Viewport.fit(world.arena(), 200, GifRecorder.height(world, 200));
            assertEquals(Pixels.hex(Palette.FLOOR), Pixels.hex(Pixels.at(reader.read(0), v, 4.5, 3.5)), "floor colour kept exactly");
            assertEquals(Pixels.hex(Palette.robot(0)), Pixels.hex(Pixels.at(reader.read(5), v, world.robot("a").x(), world.robot("a").y())),
                    "robot colour kept exactly");
        } finally {
            reader.dispose();
        }
        assertTrue(new String(bytes.toByteArray(), StandardCharsets.ISO_8859_1).contains("NETSCAPE2.0"), "loop extension");
    }

    @Test
    void frames_stayBounded_bySamplingLessOften() {
        SimWorld world = movingWorld();
        GifRecorder gif = new GifRecorder(new WorldPainter(), new Scene("film"), new GifRecorder.Settings(1, 8, 64, 50));
        world.addListener(gif);
        for (int i = 0; i < 100; i++) {
            world.step();
            assertTrue(gif.frames() <= 8, gif.frames() + " frames after step " + (i + 1));
        }
        assertTrue(gif.everySteps() >= 8, "samples every " + gif.everySteps() + " steps");
        assertTrue(gif.frames() >= 4);
    }

    @Test
    void emptyFilm_isRefused() {
        GifRecorder gif = new GifRecorder(new WorldPainter(), new Scene("film"), GifRecorder.Settings.defaults());
        IllegalStateException e = assertThrows(IllegalStateException.class, () -> gif.write(new ByteArrayOutputStream()));
        assertTrue(e.getMessage().contains("no frame"), e.getMessage());
    }

    @Test
    void settings_outOfRange_areRefusedByName() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new GifRecorder.Settings(10, 1, 200, 50));
        assertTrue(e.getMessage().contains("maxFrames 1"), e.getMessage());
    }
}
