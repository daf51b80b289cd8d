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

    @Test
    void encoder_roundTripsThroughImageIO_exactly_forNoiseAndFlatAreasAlike() throws IOException {
        // random indices fill the LZW table (clear codes, 12-bit codes); flat runs make long strings
        int width = 301;
        int height = 97;
        java.util.Random random = new java.util.Random(5);
        byte[][] frames = new byte[3][width * height];
        for (int i = 0; i < frames[0].length; i++) {
            frames[0][i] = (byte) random.nextInt(256);
            frames[1][i] = (byte) (i / 1000 % 7);
            frames[2][i] = (byte) (i % width < 150 ? random.nextInt(4) : 200);
        }
        int[] colours = new int[256];
        for (int i = 0; i < 256; i++) {
            colours[i] = i * 0x010203 & 0xFFFFFF;
            colours[i] = colours[i] ^ (i << 16);   // all 256 distinct
        }
        GifEncoder encoder = new GifEncoder();
        java.util.List<byte[]> data = new java.util.ArrayList<>();
        for (byte[] f : frames) {
            data.add(encoder.compress(f));
        }
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        GifEncoder.write(bytes, width, height, colours, data, new int[] {5, 5, 50});
        ImageReader reader = ImageIO.getImageReadersByFormatName("gif").next();
        try (ImageInputStream in = ImageIO.createImageInputStream(new ByteArrayInputStream(bytes.toByteArray()))) {
            reader.setInput(in);
            assertEquals(3, reader.getNumImages(true));
            for (int f = 0; f < 3; f++) {
                java.awt.image.BufferedImage image = reader.read(f);
                assertEquals(width, image.getWidth());
                assertEquals(height, image.getHeight());
                for (int i = 0; i < frames[f].length; i++) {
                    int expected = colours[frames[f][i] & 0xFF];
                    int got = image.getRGB(i % width, i / width) & 0xFFFFFF;
                    if (expected != got) {
                        throw new AssertionError("frame " + f + " pixel " + i + ": " + Integer.toHexString(got)
                                + " instead of " + Integer.toHexString(expected));
                    }
                }
            }
        } finally {
            reader.dispose();
        }
    }

    @Test
    void film_isTheSameBytes_forTheSameRun_framesDroppedAndEncodedAsideIncluded() throws IOException {
        byte[][] films = new byte[2][];
        for (int run = 0; run < 2; run++) {
            SimWorld world = movingWorld();
            GifRecorder gif = new GifRecorder(new WorldPainter(), new Scene("film"), new GifRecorder.Settings(3, 6, 120, 50));
            world.addListener(gif);
            for (int i = 0; i < 60; i++) {
                world.step();
            }
            assertTrue(gif.everySteps() > 3, "frames were dropped on the way");
            ByteArrayOutputStream bytes = new ByteArrayOutputStream();
            gif.write(bytes);
            films[run] = bytes.toByteArray();
        }
        org.junit.jupiter.api.Assertions.assertArrayEquals(films[0], films[1]);
    }
}
