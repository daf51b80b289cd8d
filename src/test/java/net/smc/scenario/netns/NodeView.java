package net.smc.scenario.netns;

import java.util.List;
import java.util.Map;
import java.util.Optional;
import net.smc.core.cell.CellView;

/**
 * The fields of a node's status view a test looks at, read with {@link CellView#fromJson} from the
 * JSON a node answers to {@code smc status}.
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

    /** @throws IllegalArgumentException naming the problem when {@code json} is not a status view */
    static NodeView parse(String json) {
        CellView v = CellView.fromJson(json);
        return new NodeView(v.vehicle(), v.acting(), v.epoch(), Optional.ofNullable(v.commander()),
                Optional.ofNullable(v.parent()), v.suspended(), List.copyOf(v.roles()),
                Optional.ofNullable(v.state()).map(Enum::name), Map.copyOf(v.counts()), json);
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
}
