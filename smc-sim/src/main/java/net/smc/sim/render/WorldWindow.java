package net.smc.sim.render;

import java.awt.Dimension;
import java.awt.Graphics;
import java.awt.GraphicsEnvironment;
import java.awt.HeadlessException;
import java.awt.event.KeyAdapter;
import java.awt.event.KeyEvent;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.awt.image.BufferedImage;
import java.lang.reflect.InvocationTargetException;
import java.util.Objects;
import java.util.concurrent.atomic.AtomicReference;

import javax.swing.JFrame;
import javax.swing.JPanel;
import javax.swing.SwingUtilities;
import javax.swing.WindowConstants;

import net.smc.sim.world.SimWorld;

/**
 * A live view of a world: a Swing window showing the {@link WorldPainter}'s picture, repainted
 * each time the caller {@link #show}s a frame, with keys for its {@link ViewControls}. The window
 * does not run the simulation: the caller advances it, paced by a {@link PacedLoop} on the same
 * controls, and the picture is painted on the caller's (the simulation's) thread into an image
 * that the window's event thread only copies to the screen.
 *
 * <pre>{@code
 * try (WorldWindow window = WorldWindow.open("rescue", 1200, 860, ViewControls.defaults())) {
 *     PacedLoop.realTime(window.controls(), 40)
 *             .run(scheduler::runFor, () -> window.show(world, scene), () -> window.closed() || done());
 * } catch (NoDisplayException e) {
 *     out.println(e.getMessage());             // "no display; running headless"
 * }
 * }</pre>
 */
public final class WorldWindow implements AutoCloseable {
    private final ViewControls controls;
    private final WorldPainter painter = new WorldPainter();
    private final AtomicReference<BufferedImage> latest = new AtomicReference<>();
    private final String title;
    private volatile boolean closed;
    private volatile int width;
    private volatile int height;
    private JFrame frame;
    private View view;

    private WorldWindow(String title, int width, int height, ViewControls controls) {
        this.title = title;
        this.width = width;
        this.height = height;
        this.controls = controls;
    }

    /** Whether a window can be shown here. */
    public static boolean displayAvailable() {
        return !GraphicsEnvironment.isHeadless();
    }

    /**
     * Opens a window whose drawing area is {@code width} x {@code height} pixels.
     *
     * @throws NoDisplayException with the message {@code no display; running headless} when there is no display
     */
    public static WorldWindow open(String title, int width, int height, ViewControls controls) {
        Objects.requireNonNull(title, "title");
        Objects.requireNonNull(controls, "controls");
        if (width < 64 || height < 64) {
            throw new IllegalArgumentException("window of " + width + " x " + height + " px is too small; it must be at least 64 x 64");
        }
        if (!displayAvailable()) {
            throw new NoDisplayException("no display; running headless");
        }
        WorldWindow window = new WorldWindow(title, width, height, controls);
        try {
            SwingUtilities.invokeAndWait(window::build);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted while opening the window", e);
        } catch (InvocationTargetException e) {
            if (e.getCause() instanceof HeadlessException) {
                throw new NoDisplayException("no display; running headless");
            }
            throw new IllegalStateException("the window could not be opened: " + e.getCause(), e.getCause());
        }
        return window;
    }

    private void build() {
        view = new View();
        view.setPreferredSize(new Dimension(width, height));
        frame = new JFrame(title + " - " + controls.status());
        frame.setDefaultCloseOperation(WindowConstants.DISPOSE_ON_CLOSE);
        frame.addWindowListener(new WindowAdapter() {
            @Override
            public void windowClosed(WindowEvent e) {
                closed = true;
            }
        });
        frame.addKeyListener(new KeyAdapter() {
            @Override
            public void keyTyped(KeyEvent e) {
                if (controls.key(e.getKeyChar())) {
                    frame.setTitle(title + " - " + controls.status());
                }
            }
        });
        frame.add(view);
        frame.pack();
        frame.setLocationByPlatform(true);
        frame.setVisible(true);
    }

    /** The controls the keys change; pace the simulation with them. */
    public ViewControls controls() {
        return controls;
    }

    /** Whether the user closed the window (or {@link #close} was called). */
    public boolean closed() {
        return closed;
    }

    /** Paints the world now, on the calling (simulation) thread, with the controls' overlays, and shows it. */
    public void show(SimWorld world, Scene scene) {
        if (closed) {
            return;
        }
        scene.overlays(controls.overlays());
        latest.set(painter.render(world, scene, Math.max(64, width), Math.max(64, height)));
        view.repaint();
    }

    @Override
    public void close() {
        closed = true;
        SwingUtilities.invokeLater(() -> frame.dispose());
    }

    /** Copies the latest frame to the screen and remembers the size for the next one. */
    private final class View extends JPanel {
        private static final long serialVersionUID = 1L;

        @Override
        protected void paintComponent(Graphics g) {
            super.paintComponent(g);
            width = getWidth();
            height = getHeight();
            BufferedImage image = latest.get();
            if (image != null) {
                g.drawImage(image, 0, 0, null);
            }
        }
    }
}
