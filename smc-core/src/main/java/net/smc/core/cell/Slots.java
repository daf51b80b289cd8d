package net.smc.core.cell;

import java.util.ArrayList;
import java.util.Collections;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;

import net.smc.core.mission.ManagementTree;
import net.smc.core.mission.Mission;
import net.smc.core.mission.MissionRole;

/**
 * The arithmetic of a team's seats, the same on every cell of a mission: which seat manages which,
 * each seat's identity, and which role comes first when vehicles are short. A pure function of the
 * mission and the scheme.
 *
 * <ul>
 *   <li><b>Ownership.</b> Every seat but the commander's is owned by one managing seat, whose holder
 *       discovers, assigns and watches it. Distributed: slot {@code j} of a role managed by role
 *       {@code R} belongs to slot {@code j mod optimal(R)} of {@code R} (the commander's single slot owns
 *       all of its roles' slots); so with two surveyors and two detectors, each surveyor manages one
 *       detector. Centralised: the commander owns every seat.</li>
 *   <li><b>Identity.</b> A seat's identity is {@code [mission | level | sequence]}: its role's depth
 *       in the mission's management tree, and its position in a numbering of all seats, breadth-first
 *       by role then by slot (the commander is {@code [M|0|0]}). Seats are fixed by the mission, so
 *       identities last as long as the team configuration, whoever holds them.</li>
 *   <li><b>Hosting.</b> A seat of a secondary role may be held, while no vehicle of its own is free,
 *       by the vehicle holding slot {@code j mod optimal(P)} of its primary role {@code P}.</li>
 *   <li><b>Priority.</b> Seats the minimal configuration needs come before the others; then roles in
 *       breadth-first order; then lower slots.</li>
 * </ul>
 */
public final class Slots {
    private final Mission mission;
    private final Scheme scheme;
    private final ManagementTree tree;   // Mission.tree() builds and checks it anew on every call
    private final List<String> order;
    private final Map<String, Integer> rank = new HashMap<>();
    private final Map<String, Integer> offset = new HashMap<>();

    public Slots(Mission mission, Scheme scheme) {
        this.mission = mission;
        this.scheme = scheme;
        this.tree = mission.tree();
        this.order = tree.breadthFirst();
        int next = 1;
        for (int i = 0; i < order.size(); i++) {
            String role = order.get(i);
            rank.put(role, i);
            if (role.equals(Mission.COMMANDER)) {
                offset.put(role, 0);
            } else {
                offset.put(role, next);
                next += optimal(role);
            }
        }
    }

    public Mission mission() {
        return mission;
    }

    public Scheme scheme() {
        return scheme;
    }

    /** The commander's seat. */
    public static Seat commanderSeat() {
        return new Seat(Mission.COMMANDER, 0);
    }

    /** The roles, breadth-first from the commander. */
    public List<String> roles() {
        return order;
    }

    public MissionRole role(String name) {
        return mission.role(name).orElseThrow(() -> new IllegalArgumentException("mission '" + mission.instanceName()
                + "' has no role '" + name + "'"));
    }

    /** Slots of a role: its optimal cardinality (the commander has one). */
    public int optimal(String role) {
        return role.equals(Mission.COMMANDER) ? 1 : role(role).optimal();
    }

    /** Every seat of the mission, commander first, in identity order. */
    public List<Seat> all() {
        List<Seat> seats = new ArrayList<>();
        for (String role : order) {
            for (int s = 0; s < optimal(role); s++) {
                seats.add(new Seat(role, s));
            }
        }
        return seats;
    }

    /** The level of a role in the management tree of this scheme: 0 for the commander. */
    public int level(String role) {
        if (role.equals(Mission.COMMANDER)) {
            return 0;
        }
        return scheme == Scheme.CENTRALISED ? 1 : tree.depthOf(role);
    }

    /** The sequence number of a seat: unique within the mission. */
    public int sequence(Seat seat) {
        return offset.get(seat.role()) + seat.slot();
    }

    /** The role whose holders manage {@code role}, or empty for the commander. */
    public Optional<String> managerRole(String role) {
        if (role.equals(Mission.COMMANDER)) {
            return Optional.empty();
        }
        return scheme == Scheme.CENTRALISED ? Optional.of(Mission.COMMANDER) : tree.parentOf(role);
    }

    /** The seat that owns {@code seat}, or empty for the commander's. */
    public Optional<Seat> owner(Seat seat) {
        return managerRole(seat.role()).map(m -> new Seat(m, seat.slot() % optimal(m)));
    }

    /** The roles whose seats a holder of {@code role} may own. */
    public List<String> managedRoles(String role) {
        if (scheme == Scheme.CENTRALISED) {
            return role.equals(Mission.COMMANDER) ? order.subList(1, order.size()) : List.of();
        }
        return tree.childrenOf(role);
    }

    /** The seats owned by the seat {@code manager}. */
    public List<Seat> ownedBy(Seat manager) {
        List<Seat> seats = new ArrayList<>();
        for (String child : managedRoles(manager.role())) {
            for (int s = 0; s < optimal(child); s++) {
                Seat seat = new Seat(child, s);
                if (owner(seat).orElseThrow().equals(manager)) {
                    seats.add(seat);
                }
            }
        }
        return seats;
    }

    /** For a seat of a secondary role, the seat of its primary whose vehicle may host it. */
    public Optional<Seat> host(Seat seat) {
        return role(seat.role()).primary().map(p -> new Seat(p, seat.slot() % optimal(p)));
    }

    /** Whether the minimal configuration needs this seat. */
    public boolean minimal(Seat seat) {
        return seat.role().equals(Mission.COMMANDER) || seat.slot() < role(seat.role()).minimal();
    }

    /** Priority order of seats: needed-for-minimal first, then breadth-first role, then slot. */
    public int compare(Seat a, Seat b) {
        int c = Boolean.compare(!minimal(a), !minimal(b));
        if (c != 0) {
            return c;
        }
        c = Integer.compare(rank.get(a.role()), rank.get(b.role()));
        return c != 0 ? c : Integer.compare(a.slot(), b.slot());
    }

    /** Breadth-first rank of a role: lower is more important. */
    public int rank(String role) {
        return rank.get(role);
    }

    /** {@link #rank}, or {@link Integer#MAX_VALUE} for a name that is not a role of the mission. */
    int rankOrLast(String role) {
        Integer r = rank.get(role);
        return r == null ? Integer.MAX_VALUE : r;
    }

    /**
     * The seats a vehicle holds after it is given {@code added}: the new seat, then those of
     * {@code held} that may still share the vehicle with it (the mission's colocation rules), taken
     * primary roles first and then by priority, whatever order {@code held} lists them in. Parent and
     * child both apply this, so they agree without another message.
     */
    public List<Seat> afterAssign(List<Seat> held, Seat added) {
        List<Seat> out = new ArrayList<>();
        List<String> names = new ArrayList<>();
        out.add(added);
        names.add(added.role());
        // Primary roles first, then by priority: the answer must not depend on the order the two
        // sides happen to list the seats in.
        List<Seat> ordered = new ArrayList<>(held);
        ordered.sort(java.util.Comparator.comparing((Seat s) -> role(s.role()).isSecondary()).thenComparing(this::compare));
        for (Seat s : ordered) {
            if (s.equals(added) || names.contains(s.role())) {
                continue;
            }
            names.add(s.role());
            if (mission.allowsOnOneVehicle(names)) {
                out.add(s);
            } else {
                names.remove(names.size() - 1);
            }
        }
        out.sort(java.util.Comparator.comparing((Seat s) -> role(s.role()).isSecondary()));
        return Collections.unmodifiableList(out);
    }

    /** Counts per role of a collection of seats, every role of the mission present. */
    public Map<String, Integer> count(Iterable<Seat> seats) {
        Map<String, Integer> counts = new LinkedHashMap<>();
        order.forEach(r -> counts.put(r, 0));
        seats.forEach(s -> counts.merge(s.role(), 1, Integer::sum));
        return counts;
    }
}
