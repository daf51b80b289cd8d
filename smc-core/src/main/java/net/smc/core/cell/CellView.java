package net.smc.core.cell;

import java.util.List;
import java.util.Map;

/**
 * What a cell knows of its place in the team, at one moment: the answer to {@code smc status}.
 *
 * @param vehicle    the vehicle id
 * @param mission    the mission instance
 * @param identity   {@code [mission|level|sequence]}, or null while it holds no role
 * @param epoch      the team configuration's epoch it belongs to
 * @param commander  the acting commander as far as it knows, or null
 * @param acting     whether it is the acting commander
 * @param parent     its manager, or null
 * @param suspended  whether its lease from the parent ran out (its roles then do not count)
 * @param roles      the seats it holds ({@code role#slot}), primary first
 * @param children   its children, by vehicle id, with the seats they hold
 * @param state      for the acting commander, the mission's state; otherwise null
 * @param counts     for the acting commander, holders per role in its team; otherwise empty
 * @param timeMillis the cell's clock when the view was taken
 */
public record CellView(String vehicle, String mission, String identity, long epoch, String commander, boolean acting,
                       String parent, boolean suspended, List<String> roles, Map<String, List<String>> children,
                       MissionState state, Map<String, Integer> counts, long timeMillis) {

    /** The view as one JSON object. */
    public String toJson() {
        StringBuilder b = new StringBuilder(256).append('{');
        field(b, "vehicle", vehicle).append(',');
        field(b, "mission", mission).append(',');
        field(b, "identity", identity).append(',');
        b.append("\"epoch\":").append(epoch).append(',');
        field(b, "commander", commander).append(',');
        b.append("\"acting\":").append(acting).append(',');
        field(b, "parent", parent).append(',');
        b.append("\"suspended\":").append(suspended).append(',');
        b.append("\"roles\":");
        list(b, roles).append(',');
        b.append("\"children\":{");
        boolean first = true;
        for (Map.Entry<String, List<String>> e : children.entrySet()) {
            if (!first) {
                b.append(',');
            }
            first = false;
            string(b, e.getKey()).append(':');
            list(b, e.getValue());
        }
        b.append("},");
        field(b, "missionState", state == null ? null : state.name()).append(',');
        b.append("\"counts\":{");
        first = true;
        for (Map.Entry<String, Integer> e : counts.entrySet()) {
            if (!first) {
                b.append(',');
            }
            first = false;
            string(b, e.getKey()).append(':').append(e.getValue());
        }
        b.append("},\"time\":").append(timeMillis).append('}');
        return b.toString();
    }

    private static StringBuilder field(StringBuilder b, String name, String value) {
        string(b, name).append(':');
        return value == null ? b.append("null") : string(b, value);
    }

    private static StringBuilder list(StringBuilder b, List<String> values) {
        b.append('[');
        for (int i = 0; i < values.size(); i++) {
            if (i > 0) {
                b.append(',');
            }
            string(b, values.get(i));
        }
        return b.append(']');
    }

    static StringBuilder string(StringBuilder b, String s) {
        b.append('"');
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            switch (c) {
                case '"' -> b.append("\\\"");
                case '\\' -> b.append("\\\\");
                case '\n' -> b.append("\\n");
                case '\r' -> b.append("\\r");
                case '\t' -> b.append("\\t");
                default -> {
                    if (c < 0x20) {
                        b.append(String.format("\\u%04x", (int) c));
                    } else {
                        b.append(c);
                    }
                }
            }
        }
        return b.append('"');
    }
}
