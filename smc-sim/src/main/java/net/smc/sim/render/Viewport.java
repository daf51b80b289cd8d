package net.smc.sim.render;

import net.smc.sim.arena.Arena;

/**
 * Where a world's metres land in a picture: the arena fitted, aspect kept, into the rectangle left
 * of an image once a header band and a margin are taken off, with y pointing up in the world and
 * down in the image.
 *
 * @param scale   pixels per metre
 * @param originX image x of the world's x = 0
 * @param originY image y of the world's y = 0 (the arena's bottom edge)
 * @param width   the image's width, px
 * @param height  the image's height, px
 * @param header  the height of the title band at the top, px
 */
public record Viewport(double scale, double originX, double originY, int width, int height, int header) {

    /** The viewport of {@code arena} in an image of {@code width} x {@code height} pixels. */
    public static Viewport fit(Arena arena, int width, int height) {
        if (width < 16 || height < 16) {
            throw new IllegalArgumentException("image of " + width + " x " + height + " px is too small; it must be at least 16 x 16");
        }
        int header = Math.max(14, Math.min(48, height / 16));
        double margin = Math.max(4, Math.min(width, height) / 40.0);
        double scale = Math.min((width - 2 * margin) / arena.width(), (height - header - 2 * margin) / arena.height());
        double left = (width - arena.width() * scale) / 2;
        double bottom = header + margin + (height - header - 2 * margin + arena.height() * scale) / 2;
        return new Viewport(scale, left, bottom, width, height, header);
    }

    /** The image x of world x, px. */
    public double x(double worldX) {
        return originX + worldX * scale;
    }

    /** The image y of world y, px. */
    public double y(double worldY) {
        return originY - worldY * scale;
    }

    /** A world length in pixels. */
    public double px(double metres) {
        return metres * scale;
    }
}
