package net.smc.sim.arena;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import net.smc.core.xml.XmlElement;
import net.smc.core.xml.XmlLimits;
import net.smc.core.xml.XmlReader;
import net.smc.core.xml.XmlRefusal;
import net.smc.sim.arena.Arena.Box;
import net.smc.sim.arena.Arena.Cylinder;
import net.smc.sim.arena.Arena.Door;
import net.smc.sim.arena.Arena.Hazard;
import net.smc.sim.arena.Arena.Start;
import net.smc.sim.arena.Arena.Station;
import net.smc.sim.arena.Arena.Target;
import net.smc.sim.arena.Arena.Wall;

/**
 * Reads a world file ({@code missions/worlds/*.xml}, schema {@code missions/worlds/world.xsd}) into
 * an {@link Arena}, checking every rule and listing every error as
 * {@code FILE:LINE:COL: <element>: what; rule}. Lengths are metres, angles degrees.
 *
 * <pre>{@code
 * Arena rescue = ArenaReader.read(Path.of("missions/worlds/rescue.xml"));
 * }</pre>
 */
public final class ArenaReader {
    /** How far a start position must stay from walls and obstacles: a Koala's half diagonal and a margin. */
    static final double START_CLEARANCE = 0.25;
    private static final double DEFAULT_WALL = 0.1;

    private static final Map<String, Set<String>> ATTRIBUTES = Map.of(
            "wall", Set.of("x1", "y1", "x2", "y2", "thickness"),
            "door", Set.of("id", "x1", "y1", "x2", "y2", "thickness", "open"),
            "box", Set.of("id", "x", "y", "width", "height", "angle"),
            "cylinder", Set.of("id", "x", "y", "radius"),
            "hazard", Set.of("id", "kind", "x", "y", "radius", "effect", "disables"),
            "target", Set.of("id", "kind", "x", "y", "radius"),
            "station", Set.of("id", "x", "y"),
            "start", Set.of("id", "x", "y", "heading"));
    private static final String CHILDREN = "<wall>, <door>, <box>, <cylinder>, <hazard>, <target>, <station> or <start>";

    /** World files are read with the default limits: 1 MiB, 4096 characters per text or attribute value. */
    private static final XmlReader XML = new XmlReader("world file", "missions/worlds/world.xsd", XmlLimits.DEFAULTS);

    private final Path file;
    private final List<ArenaError> errors = new ArrayList<>();
    private final Map<String, XmlElement> ids = new HashMap<>();
    private double width;
    private double height;

    private ArenaReader(Path file) {
        this.file = file;
    }

    /** Reads and checks the world file at {@code file}; a file larger than 1 MiB is refused unread. */
    public static Arena read(Path file) throws IOException, ArenaException {
        return parse(file, XML.readFile(file));
    }

    /** Checks {@code text}, a world file's content; {@code file} names it in errors. */
    public static Arena parse(Path file, String text) throws ArenaException {
        ArenaReader reader = new ArenaReader(file);
        Arena arena = reader.arena(text);
        if (!reader.errors.isEmpty()) {
            reader.errors.sort(Comparator.comparingInt(ArenaError::line).thenComparingInt(ArenaError::column));
            throw new ArenaException(reader.errors);
        }
        return arena;
    }

    private Arena arena(String text) {
        XmlElement root;
        try {
            root = XML.read(text);
        } catch (XmlRefusal e) {
            errors.add(new ArenaError(file, e.line(), e.column(), null, e.getMessage()));
            return null;
        }
        if (root == null || !root.name().equals("world")) {
            error(root, "unexpected root element; a world file's root is <world>");
            return null;
        }
        attributes(root, Set.of("name", "width", "height"));
        noText(root);
        String name = text(root, "name");
        width = positive(root, "width", Double.NaN);
        height = positive(root, "height", Double.NaN);
        List<Wall> walls = new ArrayList<>();
        List<Door> doors = new ArrayList<>();
        List<Box> boxes = new ArrayList<>();
        List<Cylinder> cylinders = new ArrayList<>();
        List<Hazard> hazards = new ArrayList<>();
        List<Target> targets = new ArrayList<>();
        List<Station> stations = new ArrayList<>();
        List<Start> starts = new ArrayList<>();
        List<XmlElement> startElements = new ArrayList<>();
        for (XmlElement el : root.children()) {
            Set<String> allowed = ATTRIBUTES.get(el.name());
            if (allowed == null) {
                error(el, "unexpected element in <world>; expected " + CHILDREN);
                continue;
            }
            attributes(el, allowed);
            noText(el);
            for (XmlElement child : el.children()) {
                error(child, "unexpected element in " + el.tag() + "; " + el.tag() + " holds no elements");
            }
            switch (el.name()) {
                case "wall" -> {
                    double[] s = segment(el);
                    walls.add(new Wall(s[0], s[1], s[2], s[3], positive(el, "thickness", DEFAULT_WALL)));
                }
                case "door" -> {
                    String id = id(el);
                    double[] s = segment(el);
                    doors.add(new Door(id, s[0], s[1], s[2], s[3], positive(el, "thickness", DEFAULT_WALL),
                            bool(el, "open", true)));
                }
                case "box" -> boxes.add(new Box(optionalId(el), x(el), y(el), positive(el, "width", Double.NaN),
                        positive(el, "height", Double.NaN), Math.toRadians(number(el, "angle", 0))));
                case "cylinder" -> cylinders.add(new Cylinder(optionalId(el), x(el), y(el),
                        positive(el, "radius", Double.NaN)));
                case "hazard" -> hazards.add(hazard(el));
                case "target" -> targets.add(new Target(id(el), word(el, "kind", "soldier"), x(el), y(el),
                        positive(el, "radius", 0.25)));
                case "station" -> stations.add(new Station(id(el), x(el), y(el)));
                case "start" -> {
                    starts.add(new Start(id(el), x(el), y(el), Math.toRadians(number(el, "heading", 0))));
                    startElements.add(el);
                }
                default -> throw new AssertionError(el.name());
            }
        }
        if (starts.isEmpty()) {
            error(root, "no <start>; a world needs at least one start position");
        }
        Arena arena = new Arena(name, width, height, walls, doors, boxes, cylinders, hazards, targets, stations, starts);
        if (errors.isEmpty()) {
            // Only a sound arena gives meaningful distances: a wall with a bad coordinate would be read as 0.
            for (int i = 0; i < starts.size(); i++) {
                clearance(arena, starts.get(i), startElements.get(i));
            }
        }
        return arena;
    }

    private Hazard hazard(XmlElement el) {
        String id = id(el);
        double radius = number(el, "radius", 0);
        if (radius < 0) {
            error(el, "radius " + radius + " is negative; a hazard's radius (its solid body) is 0 or more");
        }
        double effect = positive(el, "effect", Double.NaN);
        if (effect < radius) {
            error(el, "effect " + effect + " is less than radius " + radius
                    + "; a hazard's radius of effect must reach at least its body's edge");
        }
        return new Hazard(id, word(el, "kind", "chemical"), x(el), y(el), Math.max(0, radius), effect,
                bool(el, "disables", false));
    }

    /** Reports a start that lies within {@link #START_CLEARANCE} of a solid thing. */
    private void clearance(Arena arena, Start start, XmlElement el) {
        double nearest = Geometry2.clearance(arena, start.x(), start.y());
        if (nearest < START_CLEARANCE) {
            error(el, String.format(java.util.Locale.ROOT,
                    "start '%s' at (%.2f, %.2f) is %.2f m from a wall or obstacle; a start needs %.2f m clear",
                    start.id(), start.x(), start.y(), Math.max(0, nearest), START_CLEARANCE));
        }
    }

    private double[] segment(XmlElement el) {
        double x1 = coordinate(el, "x1", width);
        double y1 = coordinate(el, "y1", height);
        double x2 = coordinate(el, "x2", width);
        double y2 = coordinate(el, "y2", height);
        if (x1 == x2 && y1 == y2) {
            error(el, "both ends are (" + x1 + ", " + y1 + "); a " + el.tag() + " must have a length");
        }
        return new double[] {x1, y1, x2, y2};
    }

    private double x(XmlElement el) {
        return coordinate(el, "x", width);
    }

    private double y(XmlElement el) {
        return coordinate(el, "y", height);
    }

    private double coordinate(XmlElement el, String attribute, double limit) {
        double value = number(el, attribute, Double.NaN);
        if (!Double.isNaN(limit) && (value < 0 || value > limit)) {
            error(el, attribute + " " + value + " lies outside the arena; it must be within 0 to " + limit);
        }
        return value;
    }

    private double positive(XmlElement el, String attribute, double fallback) {
        double value = number(el, attribute, fallback);
        if (value <= 0) {
            error(el, attribute + " " + value + " is not positive; " + el.tag() + "'s " + attribute + " must be above 0");
        }
        return value;
    }

    /** The attribute as a finite number; {@code fallback} when absent, or an error when NaN (required). */
    private double number(XmlElement el, String attribute, double fallback) {
        String text = el.attributes().get(attribute);
        if (text == null) {
            if (Double.isNaN(fallback)) {
                error(el, "missing attribute '" + attribute + "'; " + el.tag() + " needs "
                        + required(el.name()));
                return 0;
            }
            return fallback;
        }
        try {
            double value = Double.parseDouble(text.strip());
            if (Double.isFinite(value)) {
                return value;
            }
        } catch (NumberFormatException e) {
            // reported below
        }
        error(el, "attribute '" + attribute + "' is '" + text + "'; it must be a finite decimal number");
        return 0;
    }

    private static String required(String element) {
        return switch (element) {
            case "world" -> "name, width and height";
            case "wall" -> "x1, y1, x2 and y2";
            case "door" -> "id, x1, y1, x2 and y2";
            case "box" -> "x, y, width and height";
            case "cylinder" -> "x, y and radius";
            case "hazard" -> "id, x, y and effect";
            default -> "id, x and y";
        };
    }

    private boolean bool(XmlElement el, String attribute, boolean fallback) {
        String text = el.attributes().get(attribute);
        if (text == null) {
            return fallback;
        }
        if (!text.equals("true") && !text.equals("false")) {
            error(el, "attribute '" + attribute + "' is '" + text + "'; it must be true or false");
        }
        return text.equals("true");
    }

    private String text(XmlElement el, String attribute) {
        String text = el.attributes().get(attribute);
        if (text == null || text.isBlank()) {
            error(el, (text == null ? "missing" : "empty") + " attribute '" + attribute + "'; " + el.tag()
                    + " needs " + required(el.name()));
            return "";
        }
        return text;
    }

    private String word(XmlElement el, String attribute, String fallback) {
        String text = el.attributes().get(attribute);
        if (text == null) {
            return fallback;
        }
        if (!text.matches("[A-Za-z][A-Za-z0-9_-]*")) {
            error(el, "attribute '" + attribute + "' is '" + text + "'; it must be a word (a letter, then letters, digits, _ or -)");
        }
        return text;
    }

    private String id(XmlElement el) {
        String id = text(el, "id");
        if (!id.isEmpty()) {
            if (!id.matches("[A-Za-z][A-Za-z0-9_-]*")) {
                error(el, "id '" + id + "' is not a name; an id is a letter, then letters, digits, _ or -");
            }
            XmlElement first = ids.putIfAbsent(id, el);
            if (first != null) {
                error(el, "id '" + id + "' is used already by " + first.tag() + " at line " + first.line()
                        + "; ids must be unique in a world file");
            }
        }
        return id;
    }

    private String optionalId(XmlElement el) {
        return el.attributes().containsKey("id") ? id(el) : el.name() + "@" + el.line() + ":" + el.column();
    }

    private void attributes(XmlElement el, Set<String> allowed) {
        for (String attribute : el.attributes().keySet()) {
            if (!allowed.contains(attribute)) {
                error(el, "unexpected attribute '" + attribute + "'; " + el.tag() + " takes only "
                        + String.join(", ", new LinkedHashSet<>(allowed.stream().sorted().toList())));
            }
        }
    }

    private void noText(XmlElement el) {
        if (!el.text().isEmpty()) {
            error(el, "unexpected text; " + el.tag() + " holds no text (write comments as <!-- ... -->)");
        }
    }

    private void error(XmlElement at, String message) {
        errors.add(new ArenaError(file, at == null ? 1 : at.line(), at == null ? 1 : at.column(),
                at == null ? null : at.name(), message));
    }
}
