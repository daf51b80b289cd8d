package net.smc.sim.render;

import java.awt.Color;
import java.awt.image.BufferedImage;

/** Pixel checks for pictures. */
public final class Pixels {
    private Pixels() {
    }

    /** The colour at the image pixel of world point (x, y). */
    public static Color at(BufferedImage image, Viewport v, double x, double y) {
        return new Color(image.getRGB((int) Math.floor(v.x(x)), (int) Math.floor(v.y(y))));
    }

    /** Whether two colours are within {@code tolerance} on every channel. */
    public static boolean near(Color a, Color b, int tolerance) {
        return Math.abs(a.getRed() - b.getRed()) <= tolerance && Math.abs(a.getGreen() - b.getGreen()) <= tolerance
                && Math.abs(a.getBlue() - b.getBlue()) <= tolerance;
    }

    /**
     * Whether some pixel within {@code radius} pixels (a square) of world point (x, y) is within
     * {@code tolerance} of {@code colour}: for a mark that a label drawn later may partly cover.
     */
    public static boolean nearby(BufferedImage image, Viewport v, double x, double y, int radius, Color colour, int tolerance) {
        int cx = (int) Math.floor(v.x(x));
        int cy = (int) Math.floor(v.y(y));
        for (int dy = -radius; dy <= radius; dy++) {
            for (int dx = -radius; dx <= radius; dx++) {
                int px = cx + dx;
                int py = cy + dy;
                if (px >= 0 && py >= 0 && px < image.getWidth() && py < image.getHeight()
                        && near(colour, new Color(image.getRGB(px, py)), tolerance)) {
                    return true;
                }
            }
        }
        return false;
    }

    public static String hex(Color c) {
        return String.format("#%06X", c.getRGB() & 0xFFFFFF);
    }
}
