package net.smc.policy.api;

import java.util.regex.Pattern;

/**
 * Where an object of another cell of the team lives, as PonderTalk writes it: {@code /team/<cell>}
 * (the cell itself, for {@code PonderTalk create: "/team/a1"}) or {@code /team/<cell>/<path>} (a
 * domain or object of that cell, {@code path} from its root: {@code /team/a1/role/aggregator}).
 * This replaces Ponder2's RMI URLs; a cell is named by its vehicle identifier.
 *
 * @param cell the vehicle identifier of the cell (letters, digits, {@code _ - .})
 * @param path the path below that cell's root, without a leading {@code /}; empty for the cell itself
 */
public record TeamAddress(String cell, String path) {
    /** The prefix of every team address. */
    public static final String PREFIX = "/team/";
    private static final Pattern CELL = Pattern.compile("[A-Za-z0-9_.-]{1,64}");
    private static final Pattern SEGMENT = Pattern.compile("[^/\\s]{1,64}");

    public TeamAddress {
        if (cell == null || !CELL.matcher(cell).matches()) {
            throw new PonderError("team address names cell '" + cell + "'; a cell is 1 to 64 letters, digits, '_', '-' or '.'");
        }
        if (path == null) {
            throw new PonderError("team address of cell '" + cell + "' has no path; use \"\" for the cell itself");
        }
        if (!path.isEmpty()) {
            for (String part : path.split("/", -1)) {
                if (!SEGMENT.matcher(part).matches()) {
                    throw new PonderError("team address path '" + path + "' has an empty or bad part '" + part
                            + "'; parts are separated by single '/'");
                }
            }
        }
        if (path.length() > 255) {
            throw new PonderError("team address path is " + path.length() + " characters; at most 255");
        }
    }

    /** Whether {@code text} is written as a team address (starts with {@code /team/}). */
    public static boolean isTeamAddress(Object text) {
        return text instanceof String s && s.startsWith(PREFIX);
    }

    /**
     * Parses {@code /team/<cell>[/<path>]}.
     *
     * @throws PonderError naming the text and the form when it is not one
     */
    public static TeamAddress parse(String text) {
        if (text == null || !text.startsWith(PREFIX)) {
            throw new PonderError("'" + text + "' is not a team address; the form is /team/<cell>/<path>");
        }
        String rest = text.substring(PREFIX.length());
        int slash = rest.indexOf('/');
        return slash < 0 ? new TeamAddress(rest, "") : new TeamAddress(rest.substring(0, slash), rest.substring(slash + 1));
    }

    @Override
    public String toString() {
        return PREFIX + cell + (path.isEmpty() ? "" : "/" + path);
    }
}
