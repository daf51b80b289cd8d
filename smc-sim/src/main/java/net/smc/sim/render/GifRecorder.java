package net.smc.sim.render;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;

import javax.imageio.IIOImage;
import javax.imageio.ImageIO;
import javax.imageio.ImageTypeSpecifier;
import javax.imageio.ImageWriter;
import javax.imageio.metadata.IIOInvalidTreeException;
import javax.imageio.metadata.IIOMetadata;
import javax.imageio.metadata.IIOMetadataNode;
import javax.imageio.stream.ImageOutputStream;

import net.smc.sim.world.SimWorld;
import net.smc.sim.world.WorldStepListener;

/**
 * Films a run as an animated GIF: a frame of the {@link WorldPainter}'s picture of the world and
 * its {@link Scene} every {@link Settings#everySteps} steps, small ({@link Settings#width} pixels
 * wide) and in 256 colours ({@link GifPalette}). It never holds more than {@link Settings#maxFrames} frames: when full
 * it drops every other frame and samples half as often from then on, so a long run becomes a clip
 * of the same length that plays faster. {@link #write} writes the frames with a fixed delay and
 * loops forever.
 */
public final class GifRecorder implements WorldStepListener {
    private final WorldPainter painter;
    private final Scene scene;
    private final Settings settings;
    private final List<BufferedImage> frames = new ArrayList<>();
    private final GifPalette colours = new GifPalette();
    private int every;

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
                frames.remove(i);
            }
            every *= 2;
        }
        int width = settings.width();
        int height = height(world, width);
        BufferedImage rgb = painter.render(world, scene, width, height);
        frames.add(colours.map(rgb));
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
        try (OutputStream out = Files.newOutputStream(file)) {
            write(out);
        }
    }

    /** Writes the film as a looping GIF to {@code out} (left open). */
    public void write(OutputStream out) throws IOException {
        if (frames.isEmpty()) {
            throw new IllegalStateException("no frame captured; the GIF would be empty");
        }
        ImageWriter writer = ImageIO.getImageWritersByFormatName("gif").next();
        try (ImageOutputStream stream = ImageIO.createImageOutputStream(out)) {
            writer.setOutput(stream);
            writer.prepareWriteSequence(null);
            for (int i = 0; i < frames.size(); i++) {
                BufferedImage frame = frames.get(i);
                IIOMetadata metadata = writer.getDefaultImageMetadata(ImageTypeSpecifier.createFromRenderedImage(frame), null);
                timing(metadata, colours.colourTable(), i == frames.size() - 1 ? settings.delayMillis() * 25 : settings.delayMillis(), i == 0);
                writer.writeToSequence(new IIOImage(frame, null, metadata), null);
            }
            writer.endWriteSequence();
        } finally {
            writer.dispose();
        }
    }

    /** Sets a frame's delay and, on the first frame, the NETSCAPE2.0 extension that loops the film forever. */
    private static void timing(IIOMetadata metadata, IIOMetadataNode table, int delayMillis, boolean first) throws IIOInvalidTreeException {
        String format = metadata.getNativeMetadataFormatName();
        IIOMetadataNode root = (IIOMetadataNode) metadata.getAsTree(format);
        IIOMetadataNode control = child(root, "GraphicControlExtension");
        control.setAttribute("disposalMethod", "none");
        control.setAttribute("userInputFlag", "FALSE");
        control.setAttribute("transparentColorFlag", "FALSE");
        control.setAttribute("delayTime", Integer.toString(Math.max(1, delayMillis / 10)));
        control.setAttribute("transparentColorIndex", "0");
        if (first) {
            IIOMetadataNode app = new IIOMetadataNode("ApplicationExtension");
            app.setAttribute("applicationID", "NETSCAPE");
            app.setAttribute("authenticationCode", "2.0");
            app.setUserObject(new byte[] {1, 0, 0});   // sub-block 1, loop count 0: for ever
            child(root, "ApplicationExtensions").appendChild(app);
        }
        IIOMetadataNode old = child(root, "LocalColorTable");
        root.replaceChild(table, old);
        metadata.setFromTree(format, root);
    }

    private static IIOMetadataNode child(IIOMetadataNode root, String name) {
        for (int i = 0; i < root.getLength(); i++) {
            if (root.item(i).getNodeName().equalsIgnoreCase(name)) {
                return (IIOMetadataNode) root.item(i);
            }
        }
        IIOMetadataNode node = new IIOMetadataNode(name);
        root.appendChild(node);
        return node;
    }
}
