package net.smc.sim.render;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.Rectangle;
import java.awt.RenderingHints;
import java.awt.font.FontRenderContext;
import java.awt.font.TextLayout;
import java.awt.Shape;
import java.awt.image.BufferedImage;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;

/**
 * Labels of one size for one picture, with a white halo so they read over paths and the floor.
 * A label is drawn once into an image of its own, at a whole-pixel origin, and kept (the same
 * labels come back in every frame of a film); drawing it again is copying that image.
 */
final class Text {
    /** The most label shapes kept; past it the cache starts afresh. */
    private static final int CACHED = 1_024;
    private static final Map<Key, Label> LABELS = new ConcurrentHashMap<>();
    private static final Color HALO = new Color(255, 255, 255, 200);

    private final Font font;
    private final Font bold;

    Text(int size) {
        font = new Font(Font.SANS_SERIF, Font.PLAIN, size);
        bold = font.deriveFont(Font.BOLD);
    }

    /** The font size, px. */
    int size() {
        return font.getSize();
    }

    /** Draws {@code s} with its baseline's left end at (x, y). */
    void label(Graphics2D g, String s, double x, double y, Color colour) {
        draw(g, s, x, y, colour, font);
    }

    void boldLabel(Graphics2D g, String s, double x, double y, Color colour) {
        draw(g, s, x, y, colour, bold);
    }

    /** The width of {@code s}, px. */
    double width(Graphics2D g, String s) {
        return s.isEmpty() ? 0 : new TextLayout(s, font, g.getFontRenderContext()).getAdvance();
    }

    /** The width of {@code s} in bold, px. */
    double boldWidth(Graphics2D g, String s) {
        return s.isEmpty() ? 0 : new TextLayout(s, bold, g.getFontRenderContext()).getAdvance();
    }

    private static void draw(Graphics2D g, String s, double x, double y, Color colour, Font f) {
        if (s == null || s.isEmpty()) {
            return;
        }
        Label label = label(s, f, colour, g.getFontRenderContext());
        // whole pixels: the label was drawn once at a whole-pixel origin
        g.drawImage(label.image, (int) Math.round(x) - label.originX, (int) Math.round(y) - label.originY, null);
    }

    /** The label drawn once, halo and letters, into an image of its own; kept for the next frames. */
    private static Label label(String s, Font f, Color colour, FontRenderContext context) {
        Key key = new Key(s, f, colour, context);
        Label known = LABELS.get(key);
        if (known == null) {
            Shape outline = new TextLayout(s, f, context).getOutline(null);
            float width = Math.max(2f, f.getSize() / 4f);
            Shape halo = new BasicStroke(width, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND).createStrokedShape(outline);
            Rectangle box = halo.getBounds();
            int originX = -box.x + 1;
            int originY = -box.y + 1;
            BufferedImage image = new BufferedImage(box.width + 2, box.height + 2, BufferedImage.TYPE_INT_ARGB);
            Graphics2D g = image.createGraphics();
            try {
                g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
                g.setRenderingHint(RenderingHints.KEY_STROKE_CONTROL, RenderingHints.VALUE_STROKE_PURE);
                g.translate(originX, originY);
                g.setColor(HALO);
                g.fill(halo);
                g.setColor(colour);
                g.fill(outline);
            } finally {
                g.dispose();
            }
            known = new Label(image, originX, originY);
            if (LABELS.size() >= CACHED) {
                LABELS.clear();
            }
            LABELS.put(key, known);
        }
        return known;
    }

    private record Key(String text, Font font, Color colour, FontRenderContext context) {
    }

    /** A label's picture, and where in it the baseline's left end is. */
    private record Label(BufferedImage image, int originX, int originY) {
    }
}
