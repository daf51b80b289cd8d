package net.smc.scenario.netns;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The fields of a node's status view a test looks at, read from the JSON that
 * {@code CellView.toJson()} writes (one flat object of known shape; the ids and role names of the
 * tests have no quotes or escapes, which is all this small reader handles).
 *
 * @param vehicle      the vehicle id
 * @param acting       whether it is an acting commander
 * @param epoch        its team configuration's epoch
 * @param commander    the acting commander as far as it knows, or empty
 * @param parent       its manager, or empty
 * @param suspended    whether its lease from the parent ran out
 * @param roles        its seats ({@code role#slot}), primary first
 * @param missionState for an acting commander, the mission's state ({@code FORMING}, {@code RUNNING},
 *                     {@code OPTIMAL}); otherwise empty
 * @param counts       for an acting commander, holders per role
 * @param json         the whole view, for messages
 */
record NodeView(String vehicle, boolean acting, long epoch, Optional<String> commander, Optional<String> parent,
                boolean suspended, List<String> roles, Optional<String> missionState, Map<String, Integer> counts,
                String json) {

    private static final Pattern STRING_OR_NULL = Pattern.compile("null|\"([^\"]*)\"");
    private static final Pattern QUOTED = Pattern.compile("\"([^\"]*)\"");
    private static final Pattern COUNT = Pattern.compile("\"([^\"]+)\":(\\d+)");

    /** @throws IllegalArgumentException naming the field when {@code json} lacks one */
    static NodeView parse(String json) {
        return new NodeView(optional(json, "vehicle").orElseThrow(() -> missing(json, "vehicle")),
                Boolean.parseBoolean(raw(json, "acting", "true|false")), Long.parseLong(raw(json, "epoch", "\\d+")),
                optional(json, "commander"), optional(json, "parent"),
                Boolean.parseBoolean(raw(json, "suspended", "true|false")),
                quoted(raw(json, "roles", "\\[[^\\]]*\\]")), optional(json, "missionState"),
                counts(raw(json, "counts", "\\{[^}]*\\}")), json);
    }

    /** Whether it holds a seat of {@code role}. */
    boolean holds(String role) {
        return roles.stream().anyMatch(seat -> seat.startsWith(role + "#"));
    }

    /** Whether it is an acting commander whose mission runs (RUNNING or OPTIMAL). */
    boolean running() {
        return acting && missionState.filter(s -> s.equals("RUNNING") || s.equals("OPTIMAL")).isPresent();
    }

    int count(String role) {
        return counts.getOrDefault(role, 0);
    }

    private static String raw(String json, String field, String valueRegex) {
        Matcher m = Pattern.compile("\"" + field + "\":(" + valueRegex + ")").matcher(json);
        if (!m.find()) {
            throw missing(json, field);
        }
        return m.group(1);
    }

    private static Optional<String> optional(String json, String field) {
        Matcher m = STRING_OR_NULL.matcher(raw(json, field, STRING_OR_NULL.pattern()));
        return m.matches() && m.group(1) != null ? Optional.of(m.group(1)) : Optional.empty();
    }

    private static List<String> quoted(String array) {
        List<String> values = new ArrayList<>();
        Matcher m = QUOTED.matcher(array);
        while (m.find()) {
            values.add(m.group(1));
        }
        return List.copyOf(values);
    }

    private static Map<String, Integer> counts(String object) {
        Map<String, Integer> counts = new LinkedHashMap<>();
        Matcher m = COUNT.matcher(object);
        while (m.find()) {
            counts.put(m.group(1), Integer.parseInt(m.group(2)));
        }
        return counts;
    }

    private static IllegalArgumentException missing(String json, String field) {
        return new IllegalArgumentException("status view has no field '" + field + "' of the expected form: " + json);
    }
}
