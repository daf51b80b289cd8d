package net.smc.sim.render;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.geom.Line2D;
import java.awt.geom.Rectangle2D;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

import net.smc.sim.robot.SimRobot;
import net.smc.sim.arena.Arena;
import net.smc.sim.world.SimWorld;

/** The header (title, caption, mission time), the scale bar in metres and the legend. */
final class Decorations {
    private static final double[] SCALE_STEPS = {0.5, 1, 2, 5, 10, 20, 50, 100};

    private Decorations() {
    }

    static void header(Graphics2D g, Scene scene, double timeSeconds, Viewport v, Text text) {
        double baseline = Math.min(v.header() - 3, text.size() + 3);
        String time = String.format(Locale.ROOT, "t = %.1f s", timeSeconds);
        double timeX = v.width() - 8 - text.boldWidth(g, time);
        text.boldLabel(g, time, timeX, baseline, Palette.TEXT);
        String title = fit(g, text, scene.title(), timeX - 6 - text.size(), true);
        text.boldLabel(g, title, 6, baseline, Palette.TEXT);
        double x = 6 + text.boldWidth(g, title) + text.size();
        String caption = fit(g, text, scene.caption(), timeX - x - text.size(), false);
        text.label(g, caption, x, baseline, new Color(0x555555));
    }

    /** {@code s}, cut short with an ellipsis to fit {@code room} pixels ("" when not even that fits). */
    private static String fit(Graphics2D g, Text text, String s, double room, boolean bold) {
        String cut = s;
        while (!cut.isEmpty() && (bold ? text.boldWidth(g, cut) : text.width(g, cut)) > room) {
            cut = cut.length() <= 2 ? "" : cut.substring(0, cut.length() - 2) + "\u2026";
        }
        return cut;
    }

    /** A bar of a round number of metres, about a sixth of the arena wide, under the arena's bottom-left corner. */
    static void scaleBar(Graphics2D g, Arena arena, Viewport v, Text text) {
        double metres = SCALE_STEPS[0];
        for (double step : SCALE_STEPS) {
            if (step <= arena.width() / 5) {
                metres = step;
            }
        }
        double x = v.x(0) + 8;
        double y = v.y(0) - 8;
        double len = v.px(metres);
        g.setColor(Palette.TEXT);
        g.setStroke(new BasicStroke(2f));
        g.draw(new Line2D.Double(x, y, x + len, y));
        g.draw(new Line2D.Double(x, y - 4, x, y + 1));
        g.draw(new Line2D.Double(x + len, y - 4, x + len, y + 1));
        String label = (metres == Math.rint(metres) ? String.valueOf((long) metres) : String.valueOf(metres)) + " m";
        text.label(g, label, x + len / 2 - text.width(g, label) / 2, y - 5, Palette.TEXT);
    }

    /** A boxed key in the arena's top-right corner: each robot with its colour and role, then the symbols. */
    static void legend(Graphics2D g, SimWorld world, Scene scene, Viewport v, Text text) {
        List<Row> rows = new ArrayList<>();
        for (int i = 0; i < world.robots().size(); i++) {
            SimRobot robot = world.robots().get(i);
            String role = scene.roles().label(robot.id());
            String state = robot.disabled() ? " - stopped" : "";
            rows.add(new Row(Palette.robot(i), robot.id() + (role == null || role.isEmpty() ? "" : ": " + role) + state));
        }
        if (!world.arena().hazards().isEmpty()) {
            rows.add(new Row(Palette.HAZARD, "hazard (ring: its reach)"));
        }
        if (!world.arena().targets().isEmpty()) {
            rows.add(new Row(Palette.SOLDIER, "soldier / target"));
        }
        boolean crosses = world.robots().stream().anyMatch(SimRobot::disabled)
                || scene.marks().stream().anyMatch(m -> m instanceof Mark.Cross);
        if (crosses) {
            rows.add(new Row(Palette.MARK, "X where a robot stopped"));
        }
        if (scene.marks().stream().anyMatch(m -> m instanceof Mark.Found)) {
            rows.add(new Row(Palette.FOUND, "hazard on the team's map"));
        }
        if (scene.map() != null) {
            rows.add(new Row(Palette.UNMAPPED, "not on the team's map"));
        }
        if (scene.marks().stream().anyMatch(m -> m instanceof Mark.AvoidedZone)) {
            rows.add(new Row(Palette.ZONE, "avoided zone (dashed)"));
        }
        double line = text.size() * 1.45;
        double swatch = text.size() * 0.9;
        double widest = 0;
        for (Row row : rows) {
            widest = Math.max(widest, text.width(g, row.text()));
        }
        double w = widest + swatch + text.size() * 1.6;
        double h = rows.size() * line + text.size() * 0.6;
        double x = v.x(world.arena().width()) - w - 6;
        double y = v.y(world.arena().height()) + 6;
        g.setColor(new Color(255, 255, 255, 215));
        g.fill(new Rectangle2D.Double(x, y, w, h));
        g.setColor(new Color(0x999999));
        g.setStroke(new BasicStroke(1f));
        g.draw(new Rectangle2D.Double(x, y, w, h));
        for (int i = 0; i < rows.size(); i++) {
            double top = y + text.size() * 0.4 + i * line;
            g.setColor(rows.get(i).colour());
            g.fill(new Rectangle2D.Double(x + text.size() * 0.5, top + (line - swatch) / 2, swatch, swatch));
            text.label(g, rows.get(i).text(), x + text.size() + swatch, top + line * 0.72, Palette.TEXT);
        }
    }

    /** A line of the legend. */
    private record Row(Color colour, String text) {
    }
}
