package net.smc.sim.render;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.font.FontRenderContext;
import java.awt.font.TextLayout;
import java.awt.geom.AffineTransform;
import java.awt.Shape;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;

/**
 * Labels of one size for one picture, with a white halo so they read over paths and the floor.
 * A label's outline and halo are laid out once and kept (the same labels come back in every frame
 * of a film), then filled where the label goes.
 */
final class Text {
    /** The most label shapes kept; past it the cache starts afresh. */
    private static final int CACHED = 1_024;
    private static final Map<Key, Glyphs> SHAPES = new ConcurrentHashMap<>();
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
        Glyphs glyphs = glyphs(s, f, g.getFontRenderContext());
        AffineTransform saved = g.getTransform();
        g.translate(x, y);
        g.setColor(HALO);
        g.fill(glyphs.halo);
        g.setColor(colour);
        g.fill(glyphs.outline);
        g.setTransform(saved);
    }

    private static Glyphs glyphs(String s, Font f, FontRenderContext context) {
        Key key = new Key(s, f, context);
        Glyphs known = SHAPES.get(key);
        if (known == null) {
            Shape outline = new TextLayout(s, f, context).getOutline(null);
            Shape halo = new BasicStroke(Math.max(2f, f.getSize() / 4f), BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND)
                    .createStrokedShape(outline);
            known = new Glyphs(outline, halo);
            if (SHAPES.size() >= CACHED) {
                SHAPES.clear();
            }
            SHAPES.put(key, known);
        }
        return known;
    }

    private record Key(String text, Font font, FontRenderContext context) {
    }

    /** A label's letters and the halo round them, with the baseline's left end at (0, 0). */
    private record Glyphs(Shape outline, Shape halo) {
    }
}
