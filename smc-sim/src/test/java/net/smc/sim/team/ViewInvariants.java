package net.smc.sim.team;

import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;

import net.smc.core.capability.CapabilityDescription;
import net.smc.core.cell.CellView;
import net.smc.core.cell.Scheme;
import net.smc.core.cell.Seat;
import net.smc.core.cell.Slots;
import net.smc.core.mission.Mission;
import net.smc.core.mission.MissionRole;
import net.smc.core.team.TeamConfiguration;
import net.smc.core.team.TeamPlanner;

/**
 * The safety rules of {@code TeamInvariants} (rules 1 to 3), checked on the views cells report
 * ({@link CellView}), for teams whose cells a test cannot reach into at one instant, such as cells
 * on UDP with a thread each:
 * <ol>
 *   <li>the parent relation has no cycle (a cell has one parent field, so at most one parent);</li>
 *   <li>in each team (the cells attached to one acting commander: not suspended, and every cell on
 *       the way up attached too) no seat has two holders, and no slot lies beyond its role's
 *       reasonably-optimal cardinality;</li>
 *   <li>every attached holder's vehicle meets its role's requirement.</li>
 * </ol>
 * Views are read one cell after another, not at one instant, so a single round may show a seat
 * in the middle of a hand-over at both ends; {@link UdpTeam#await} counts a rule as broken only when
 * two rounds in a row show it.
 *
 * <p>{@link #unsettled} is {@code TeamInvariants.unsettled()} on views: the liveness goal a team
 * must reach once faults stop.
 */
final class ViewInvariants {
    private ViewInvariants() {
    }

    /**
     * The first rule the views break, if any.
     *
     * @param views    the live cells' views by vehicle id
     * @param mission  the mission they run
     * @param vehicles what each vehicle can do, by id
     */
    static Optional<String> violation(Map<String, CellView> views, Mission mission,
                                      Map<String, CapabilityDescription> vehicles) {
        for (CellView v : views.values()) {
            Set<String> seen = new HashSet<>();
            for (CellView at = v; at != null && at.parent() != null; at = views.get(at.parent())) {
                if (!seen.add(at.vehicle())) {
                    return Optional.of("the parent relation has a cycle through " + seen);
                }
            }
        }
        Map<String, Map<Seat, String>> holders = new HashMap<>();
        for (CellView v : views.values()) {
            Optional<String> team = root(v, views);
            if (team.isEmpty()) {
                continue;
            }
            for (String s : v.roles()) {
                Seat seat = seat(s);
                String other = holders.computeIfAbsent(team.get(), k -> new HashMap<>()).put(seat, v.vehicle());
                if (other != null) {
                    return Optional.of("seat " + seat + " has two holders in the team of " + team.get() + ": " + other
                            + " and " + v.vehicle());
                }
                Optional<MissionRole> role = mission.role(seat.role());
                if (role.isEmpty()) {
                    return Optional.of(v.vehicle() + " holds " + seat + " of a role the mission does not have");
                }
                int optimal = seat.role().equals(Mission.COMMANDER) ? 1 : role.get().optimal();
                if (seat.slot() >= optimal) {
                    return Optional.of(v.vehicle() + " holds " + seat + " beyond the optimal cardinality " + optimal);
                }
                CapabilityDescription d = vehicles.get(v.vehicle());
                if (!role.get().requirement().isMetBy(d)) {
                    return Optional.of(v.vehicle() + " holds " + seat + " but lacks "
                            + role.get().requirement().missingFrom(d).describe());
                }
            }
        }
        return Optional.empty();
    }

    /**
     * Why the team has not settled on the best configuration its running vehicles allow (empty when
     * it has): one acting commander, and in its team per role as many holders as the
     * {@link TeamPlanner} gives for the running vehicles, capped by the seats the tree can manage (a
     * detector's seat needs its surveyor's seat held); when every role can have a vehicle of its
     * own, no vehicle holds several seats.
     */
    static String unsettled(Map<String, CellView> views, Mission mission, Map<String, CapabilityDescription> vehicles) {
        List<String> commanders = views.values().stream().filter(CellView::acting).map(CellView::vehicle).toList();
        if (commanders.size() != 1) {
            return "acting commanders: " + commanders;
        }
        String cdr = commanders.get(0);
        List<CellView> team = views.values().stream().filter(v -> root(v, views).equals(Optional.of(cdr))).toList();
        Map<String, Integer> have = new LinkedHashMap<>();
        Set<Seat> held = new HashSet<>();
        mission.roleNames().forEach(r -> have.put(r, 0));
        team.forEach(v -> v.roles().forEach(s -> {
            Seat seat = seat(s);
            held.add(seat);
            have.merge(seat.role(), 1, Integer::sum);
        }));
        TeamConfiguration plan = TeamPlanner.plan(mission, views.keySet().stream()
                .map(id -> vehicles.get(id).summary()).toList(), cdr);
        Slots slots = new Slots(mission, mission.parameter("scheme")
                .map(p -> Scheme.parse(String.valueOf(p.value()))).orElse(Scheme.DISTRIBUTED));
        Map<String, Integer> want = new LinkedHashMap<>();
        mission.roleNames().forEach(r -> want.put(r, Math.min(plan.holdersOf(r).size(), capacity(slots, r, held))));
        if (!have.equals(want)) {
            return "holders " + have + ", the running vehicles allow " + want;
        }
        if (plan.optimalReached()) {
            List<String> hosting = team.stream().filter(v -> v.roles().size() > 1).map(CellView::vehicle).toList();
            if (!hosting.isEmpty()) {
                return "the running vehicles allow every role a vehicle of its own, but " + hosting + " hold several";
            }
        }
        return "";
    }

    /** Seats of {@code role} whose owning seat is held: the most holders the tree can manage now. */
    private static int capacity(Slots slots, String role, Set<Seat> held) {
        int n = 0;
        for (int slot = 0; slot < slots.optimal(role); slot++) {
            Optional<Seat> owner = slots.owner(new Seat(role, slot));
            if (owner.isEmpty() || held.contains(owner.get())) {
                n++;
            }
        }
        return n;
    }

    /** The acting commander a cell is attached to, if it is attached. */
    static Optional<String> root(CellView v, Map<String, CellView> views) {
        CellView at = v;
        for (int depth = 0; depth < 64 && at != null; depth++) {
            if (at.acting()) {
                return Optional.of(at.vehicle());
            }
            if (at.suspended() || at.parent() == null) {
                return Optional.empty();
            }
            at = views.get(at.parent());
        }
        return Optional.empty();
    }

    /** {@code role#slot}, as views write seats. */
    static Seat seat(String text) {
        int hash = text.lastIndexOf('#');
        return new Seat(text.substring(0, hash), Integer.parseInt(text.substring(hash + 1)));
    }
}
