package net.smc.sim.render;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.font.TextLayout;
import java.awt.geom.AffineTransform;
import java.awt.Shape;

/** Labels of one size for one picture, with a white halo so they read over paths and the floor. */
final class Text {
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
        Shape outline = new TextLayout(s, f, g.getFontRenderContext()).getOutline(AffineTransform.getTranslateInstance(x, y));
        g.setColor(new Color(255, 255, 255, 200));
        g.setStroke(new BasicStroke(Math.max(2f, f.getSize() / 4f), BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
        g.draw(outline);
        g.setColor(colour);
        g.fill(outline);
    }
}
