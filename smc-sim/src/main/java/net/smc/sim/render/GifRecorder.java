package net.smc.sim.render;

import java.awt.image.BufferedImage;
import java.awt.image.DataBufferInt;
import java.io.BufferedOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Future;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.ThreadPoolExecutor;
import java.util.concurrent.TimeUnit;

import net.smc.sim.world.SimWorld;
import net.smc.sim.world.WorldStepListener;

/**
 * Films a run as an animated GIF: a frame of the {@link WorldPainter}'s picture of the world and
 * its {@link Scene} every {@link Settings#everySteps} steps, small ({@link Settings#width} pixels
 * wide) and in 256 colours ({@link GifPalette}). It never holds more than {@link Settings#maxFrames} frames: when full
 * it drops every other frame and samples half as often from then on, so a long run becomes a clip
 * of the same length that plays faster. {@link #write} writes the frames with a fixed delay and
 * loops forever.
 *
 * <p>A frame is painted on the simulation's thread (the painter reads the world as it is), and its
 * pixels are handed to a thread of the recorder's own that maps them to the palette and
 * compresses them ({@link GifEncoder}) while the simulation runs on; at most
 * {@value #MAX_PENDING} frames wait for it, so a slow encoder holds the simulation back rather
 * than fill the memory. The film's bytes do not depend on the timing of that thread.
 */
public final class GifRecorder implements WorldStepListener {
    private final WorldPainter painter;
    private final Scene scene;
    private final Settings settings;
    /** The most frames painted and not yet compressed. */
    static final int MAX_PENDING = 8;
    private final List<Future<byte[]>> frames = new ArrayList<>();
    // used only on the encoding thread
    private final GifPalette colours = new GifPalette();
    private final GifEncoder encoder = new GifEncoder();
    private ExecutorService encoding;
    private int every;
    private int frameWidth;
    private int frameHeight;

    /**
     * The film's settings.
     *
     * @param everySteps  world steps between frames at first (1 or more)
     * @param maxFrames   the most frames kept (2 to 2,000)
     * @param width       frame width, px (64 to 1,920); the height follows the arena's shape
     * @param delayMillis how long each frame shows, ms (10 to 10,000; GIF counts hundredths of a second)
     */
    public record Settings(int everySteps, int maxFrames, int width, int delayMillis) {
        public Settings {
            check("everySteps", everySteps, 1, Integer.MAX_VALUE);
            check("maxFrames", maxFrames, 2, 2_000);
            check("width", width, 64, 1_920);
            check("delayMillis", delayMillis, 10, 10_000);
        }

        /** A frame every 25 steps (0.5 s at 20 ms), at most 150 frames, 560 px wide, 80 ms each. */
        public static Settings defaults() {
            return new Settings(25, 150, 560, 80);
        }

        private static void check(String name, int value, int min, int max) {
            if (value < min || value > max) {
                throw new IllegalArgumentException("GIF " + name + " " + value + " is out of range; it must be " + min + " to " + max);
            }
        }
    }

    public GifRecorder(WorldPainter painter, Scene scene, Settings settings) {
        this.painter = Objects.requireNonNull(painter, "painter");
        this.scene = Objects.requireNonNull(scene, "scene");
        this.settings = Objects.requireNonNull(settings, "settings");
        this.every = settings.everySteps();
    }

    @Override
    public void stepped(SimWorld world) {
        if (world.steps() % every == 0) {
            capture(world);
        }
    }

    /** Takes a frame now (the listener does so every few steps; call it for the last picture of a run). */
    public void capture(SimWorld world) {
        if (frames.size() >= settings.maxFrames()) {
            for (int i = frames.size() - 1; i > 0; i -= 2) {
                frames.remove(i).cancel(false);
            }
            every *= 2;
        }
        int width = settings.width();
        int height = height(world, width);
        if (frames.isEmpty()) {
            frameWidth = width;
            frameHeight = height;
        } else if (width != frameWidth || height != frameHeight) {
            throw new IllegalStateException("a frame of " + width + "x" + height + " px in a film of " + frameWidth
                    + "x" + frameHeight + " px; every frame of a film must have the same size");
        }
        BufferedImage rgb = painter.render(world, scene, width, height);
        int[] pixels = ((DataBufferInt) rgb.getRaster().getDataBuffer()).getData();
        waitForBacklog();
        if (encoding == null) {
            // one thread, in the order of the frames; it ends when idle for a second
            ThreadPoolExecutor one = new ThreadPoolExecutor(1, 1, 1, TimeUnit.SECONDS, new LinkedBlockingQueue<>(), r -> {
                Thread t = new Thread(r, "gif-encoder");
                t.setDaemon(true);
                return t;
            });
            one.allowCoreThreadTimeOut(true);
            encoding = one;
        }
        frames.add(encoding.submit(() -> {
            byte[] indices = new byte[pixels.length];
            colours.indices(pixels, indices);
            return encoder.compress(indices);
        }));
    }

    /** Waits until fewer than {@link #MAX_PENDING} frames are still to be compressed. */
    private void waitForBacklog() {
        int pending = 0;
        for (Future<byte[]> f : frames) {
            pending += f.isDone() ? 0 : 1;
        }
        for (int i = 0; i < frames.size() && pending >= MAX_PENDING; i++) {
            if (!frames.get(i).isDone()) {
                compressed(frames.get(i));
                pending--;
            }
        }
    }

    private static byte[] compressed(Future<byte[]> frame) {
        try {
            return frame.get();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted while a GIF frame was compressed", e);
        } catch (ExecutionException e) {
            throw new IllegalStateException("compressing a GIF frame failed: " + e.getCause(), e.getCause());
        }
    }

    /** The frame height for an arena's shape at {@code width} px: the arena's aspect plus the header. */
    static int height(SimWorld world, int width) {
        double aspect = world.arena().height() / world.arena().width();
        return (int) Math.round(width * aspect) + Math.max(14, width / 20);
    }

    /** How many frames are held. */
    public int frames() {
        return frames.size();
    }

    /** The world steps between frames now. */
    public int everySteps() {
        return every;
    }

    /** Writes the film to {@code file}. */
    public void write(Path file) throws IOException {
        try (OutputStream out = new BufferedOutputStream(Files.newOutputStream(file))) {
            write(out);
        }
    }

    /**
     * Writes the film as a looping GIF to {@code out} (left open), once every frame is compressed;
     * the last frame shows 25 times as long as the others.
     */
    public void write(OutputStream out) throws IOException {
        if (frames.isEmpty()) {
            throw new IllegalStateException("no frame captured; the GIF would be empty");
        }
        List<byte[]> data = new ArrayList<>(frames.size());
        for (Future<byte[]> f : frames) {
            data.add(compressed(f));
        }
        int[] delays = new int[data.size()];
        for (int i = 0; i < delays.length; i++) {
            int millis = i == delays.length - 1 ? settings.delayMillis() * 25 : settings.delayMillis();
            delays[i] = Math.max(1, millis / 10);
        }
        GifEncoder.write(out, frameWidth, frameHeight, colours.colours(), data, delays);
        out.flush();
    }
}
