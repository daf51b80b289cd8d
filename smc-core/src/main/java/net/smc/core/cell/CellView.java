package net.smc.core.cell;

import com.fasterxml.jackson.annotation.JsonProperty;
import com.fasterxml.jackson.annotation.JsonPropertyOrder;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.DeserializationFeature;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.json.JsonMapper;
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
 *
 * <p>As JSON ({@link #toJson}, {@link #fromJson}) it is one object with these fields in this order,
 * except that {@code state} is named {@code missionState} and {@code timeMillis} is {@code time};
 * absent values are {@code null}.
 */
@JsonPropertyOrder({"vehicle", "mission", "identity", "epoch", "commander", "acting", "parent", "suspended",
        "roles", "children", "missionState", "counts", "time"})
public record CellView(String vehicle, String mission, String identity, long epoch, String commander, boolean acting,
                       String parent, boolean suspended, List<String> roles, Map<String, List<String>> children,
                       @JsonProperty("missionState") MissionState state, Map<String, Integer> counts,
                       @JsonProperty("time") long timeMillis) {

    private static final ObjectMapper JSON = JsonMapper.builder()
            .enable(DeserializationFeature.FAIL_ON_NULL_FOR_PRIMITIVES)
            .enable(DeserializationFeature.FAIL_ON_MISSING_CREATOR_PROPERTIES)
            .build();

    /** The view as one JSON object. */
    public String toJson() {
        try {
            return JSON.writeValueAsString(this);
        } catch (JsonProcessingException e) {
            throw new IllegalStateException("cannot write the view of " + vehicle + " as JSON: " + e.getMessage(), e);
        }
    }

    /**
     * Reads a view written by {@link #toJson} (for example a node's answer to {@code smc status}).
     *
     * @throws IllegalArgumentException when {@code json} is not such an object, naming the problem
     */
    public static CellView fromJson(String json) {
        try {
            CellView view = JSON.readValue(json, CellView.class);
            if (view.vehicle == null || view.roles == null || view.children == null || view.counts == null) {
                throw new IllegalArgumentException("not a status view (vehicle, roles, children and counts are "
                        + "required): " + json);
            }
            return view;
        } catch (JsonProcessingException e) {
            throw new IllegalArgumentException("not a status view: " + e.getOriginalMessage(), e);
        }
    }
}
