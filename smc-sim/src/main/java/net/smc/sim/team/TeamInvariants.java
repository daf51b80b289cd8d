package net.smc.sim.team;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;

import net.smc.core.capability.CapabilityDescription;
import net.smc.core.capability.CapabilitySummary;
import net.smc.core.cell.Cell;
import net.smc.core.cell.Seat;
import net.smc.core.mission.Mission;
import net.smc.core.mission.MissionRole;
import net.smc.core.team.TeamConfiguration;
import net.smc.core.team.TeamPlanner;
import net.smc.core.transport.sim.LinkProfile;

/**
 * What must hold of a simulated team after every step, and what it must reach once faults stop.
 *
 * <p>Safety, after every step:
 * <ol>
 *   <li>the parent relation among live cells has no cycle (each cell has at most one parent by
 *       construction);</li>
 *   <li>in each team (the cells attached to one acting commander: each holds a live lease from a
 *       parent that lists it as a child, all the way up) no seat has two holders, so no role has
 *       more holders than its reasonably-optimal cardinality;</li>
 *   <li>a cell whose parent is gone or no longer lists it loses its lease within the lease time
 *       plus two heartbeats;</li>
 *   <li>every attached holder is authenticated (not the rogue) and capable (its vehicle meets the
 *       role's requirement);</li>
 *   <li>two acting commanders that can hear each other do not stay so for longer than the merge
 *       bound; a single connected part has at most one commander beyond it;</li>
 *   <li>a rogue vehicle holds nothing, and no honest cell names it as parent, child or commander.</li>
 * </ol>
 *
 * <p>Liveness ({@link #settled()}): one acting commander among live cells; in its team every role
 * has the number of holders the {@link TeamPlanner} gives for the live honest vehicles, capped by
 * the seats the tree can manage (a detector's seat needs its surveyor's seat held: with one surveyor
 * left of two, one detector seat has no manager); and the configuration is maximal: no free vehicle
 * could take a vacant seat, or a secondary seat carried beside another role. (The planner may reach
 * "a vehicle of its own for every role" by trading vehicles between subtrees, which managers that
 * see only their own subtree cannot; {@link #matchesPlan()} tells whether a run got there too.)
 */
public final class TeamInvariants {
    private final TeamSimulation sim;
    private final long mergeBoundMillis;
    private final Map<String, Long> metSince = new HashMap<>();
    private final Map<String, Long> danglingSince = new HashMap<>();
    /** Each vehicle's capability description: made once, a vehicle's kit never changes. */
    private final Map<String, CapabilityDescription> descriptions = new HashMap<>();
    /** The roles each vehicle's description has been found to meet the requirement of (both fixed). */
    private final Map<String, Set<String>> meets = new HashMap<>();
    /** What the last check read of the cells, and whether the structural rules passed on it. */
    private final CellReadings<Cell> readings;
    private long checks;
    private long structuralWalks;

    TeamInvariants(TeamSimulation sim, long mergeBoundMillis, boolean verifyingReadings) {
        this.sim = sim;
        this.mergeBoundMillis = mergeBoundMillis;
        this.readings = CellReadings.ofCells().verifying(verifyingReadings);
    }

    /** The merge bound in use: given, or ten beacon periods (tolerates heavy loss) plus a failure timeout. */
    public long mergeBoundMillis() {
        if (mergeBoundMillis >= 0) {
            return mergeBoundMillis;
        }
        long com = number("comTimeout");
        return 10L * net.smc.core.cell.Timing.BEACON_TICKS * com + number("failureTimeout");
    }

    private long number(String name) {
        return sim.mission().parameter(name).map(p -> ((Number) p.value()).longValue()).orElse(1000L);
    }

    public long checks() {
        return checks;
    }

    /** Tells the checks that {@code cell}'s links changed (its {@link Cell#onLinksChanged} listener). */
    void moved(Cell cell) {
        readings.moved(cell);
    }

    /** @throws InvariantViolation naming the rule, the cells involved, the seed and the trace */
    void check() {
        checks++;
        List<Cell> cells = sim.cells();
        if (readings.read(cells, sim.nowMillis())) {
            checkStructure(cells);
            readings.passed();
            structuralWalks++;
        }
        checkDangling();
        checkRogues(cells);
        checkCommanders(readings.commanders());
    }

    /**
     * How many checks walked the structural rules (no cycle, one holder per seat in a team,
     * cardinality, capability): the others read exactly what the last passed walk had read
     * ({@link CellReadings}), so those rules held again.
     */
    public long structuralWalks() {
        return structuralWalks;
    }

    /** Rules 1, 2 and 4 but rogues: functions of {@link CellReadings}' readings alone. */
    private void checkStructure(List<Cell> cells) {
        ParentLinks<Cell> links = ParentLinks.of(cells);   // each cell's links read once, for the whole walk
        Set<String> cycle = links.cycle();
        if (cycle != null) {
            fail("the parent relation has a cycle through " + cycle);
        }
        Map<String, List<Cell>> teams = links.teams();
        Mission mission = sim.mission();
        for (Map.Entry<String, List<Cell>> team : teams.entrySet()) {
            Map<Seat, String> holders = new HashMap<>();
            for (Cell c : team.getValue()) {
                CapabilityDescription description = descriptions.computeIfAbsent(c.vehicle(),
                        id -> sim.vehicle(id).description());
                for (Seat s : c.seats()) {
                    String other = holders.put(s, c.vehicle());
                    if (other != null) {
                        fail("seat " + s + " has two holders in the team of " + team.getKey() + ": " + other + " and "
                                + c.vehicle());
                    }
                    if (s.slot() >= optimal(mission, s.role())) {
                        fail(c.vehicle() + " holds " + s + " beyond the optimal cardinality of " + s.role());
                    }
                    Set<String> met = meets.computeIfAbsent(c.vehicle(), id -> new HashSet<>());
                    if (met.contains(s.role())) {
                        continue;
                    }
                    MissionRole role = mission.role(s.role()).orElseThrow();
                    if (role.requirement().isMetBy(description)) {
                        met.add(s.role());
                    } else {
                        fail(c.vehicle() + " holds " + s + " but lacks " + role.requirement().missingFrom(description)
                                .describe());
                    }
                }
            }
        }
    }

    private static int optimal(Mission mission, String role) {
        return role.equals(Mission.COMMANDER) ? 1 : mission.role(role).orElseThrow().optimal();
    }

    /** Attached cells by the acting commander they hang from (see {@link ParentLinks#teams()}). */
    static Map<String, List<Cell>> teams(List<Cell> cells) {
        return ParentLinks.of(cells).teams();
    }

    /**
     * A cell whose parent is gone or no longer lists it (a dropped Leave, a crash) keeps a lease it
     * should not: it must lose it within the lease plus two heartbeats.
     */
    private void checkDangling() {
        CellReadings<Cell> links = readings;
        long now = sim.nowMillis();
        long bound = net.smc.core.cell.Timing.of(sim.mission()).leaseMillis() + 2 * number("comTimeout");
        Set<String> dangling = new HashSet<>();
        for (int i = 0; i < links.size(); i++) {
            if (links.acting(i) || links.suspended(i) || links.parent(i) == null || links.listedByParent(i)) {
                continue;
            }
            String key = links.vehicle(i) + "->" + links.parent(i);
            dangling.add(key);
            long since = danglingSince.computeIfAbsent(key, k -> now);
            if (now - since > bound) {
                fail(links.vehicle(i) + " has held a lease from " + links.parent(i) + " for " + (now - since)
                        + " ms although that parent is gone or does not list it; the bound is " + bound + " ms");
            }
        }
        danglingSince.keySet().retainAll(dangling);
    }

    private void checkRogues(List<Cell> honest) {
        for (SimVehicle v : sim.rogues()) {
            Cell rogue = sim.cell(v.id());
            if (rogue != null && !v.commander() && !rogue.seats().isEmpty()) {
                fail("rogue " + v.id() + " holds " + rogue.seats());
            }
            for (Cell c : honest) {
                if (c.parent().filter(v.id()::equals).isPresent() || c.children().containsKey(v.id())
                        || c.commander().filter(v.id()::equals).isPresent()) {
                    fail("honest " + c.vehicle() + " names rogue " + v.id() + " as parent, child or commander");
                }
            }
        }
    }

    private void checkCommanders(List<Cell> commanders) {
        if (commanders.size() < 2 && metSince.isEmpty()) {
            return;   // no pair to check, none remembered
        }
        Set<String> pairs = new HashSet<>();
        long now = sim.nowMillis();
        List<Set<String>> parts = commanders.size() < 2 ? List.of() : sim.parts();
        for (int i = 0; i < commanders.size(); i++) {
            for (int j = i + 1; j < commanders.size(); j++) {
                String a = commanders.get(i).vehicle();
                String b = commanders.get(j).vehicle();
                if (!samePart(parts, a, b)) {
                    continue;
                }
                String key = a + "|" + b;
                pairs.add(key);
                long since = metSince.computeIfAbsent(key, k -> now);
                if (now - since > mergeBoundMillis()) {
                    fail("acting commanders " + a + " and " + b + " have heard each other for " + (now - since)
                            + " ms, beyond the merge bound of " + mergeBoundMillis() + " ms");
                }
            }
        }
        metSince.keySet().retainAll(pairs);
    }

    private static boolean samePart(List<Set<String>> parts, String a, String b) {
        for (Set<String> p : parts) {
            if (p.contains(a) && p.contains(b)) {
                return true;
            }
        }
        return false;
    }

    /**
     * Whether the team has settled on the best configuration its live vehicles allow: one acting
     * commander, every live honest vehicle attached to it or spare, and per role as many holders as
     * the planner gives.
     */
    public boolean settled() {
        return unsettled().isEmpty();
    }

    /**
     * Settled, or dissolved: no acting commander is left (the commander and every backup that
     * could have taken over are gone) and every live honest vehicle is free again.
     */
    public boolean settledOrDissolved() {
        if (!sim.commanders().isEmpty()) {
            return settled();
        }
        return sim.cells().stream().allMatch(c -> c.seats().isEmpty() && c.parent().isEmpty());
    }

    /** Why the team has not settled (empty when it has). */
    public String unsettled() {
        List<Cell> commanders = sim.commanders();
        if (commanders.size() != 1) {
            return "acting commanders: " + commanders.stream().map(Cell::vehicle).toList();
        }
        Cell cdr = commanders.get(0);
        List<Cell> cells = sim.cells();
        Map<String, Cell> byId = new HashMap<>();
        cells.forEach(c -> byId.put(c.vehicle(), c));
        List<Cell> team = teams(cells).getOrDefault(cdr.vehicle(), List.of());
        Map<String, Integer> have = new LinkedHashMap<>();
        sim.mission().roleNames().forEach(r -> have.put(r, 0));
        team.forEach(c -> c.seats().forEach(s -> have.merge(s.role(), 1, Integer::sum)));
        TeamConfiguration plan = plan(cdr.vehicle());
        Map<String, Integer> want = new LinkedHashMap<>();
        sim.mission().roleNames().forEach(r -> want.put(r, plan.holdersOf(r).size()));
        Set<Seat> held = new HashSet<>();
        team.forEach(c -> held.addAll(c.seats()));
        for (Map.Entry<String, Integer> e : want.entrySet()) {
            e.setValue(Math.min(e.getValue(), capacity(cdr, e.getKey(), held)));
        }
        if (!have.equals(want)) {
            return "holders " + have + ", the live vehicles allow " + want;
        }
        // Maximal: no free vehicle is left idle that could take a vacant seat the tree can manage,
        // or a secondary seat that a vehicle of another role carries beside its own.
        Map<Seat, String> holder = new HashMap<>();
        team.forEach(c -> c.seats().forEach(st -> holder.put(st, c.vehicle())));
        for (Cell free : cells) {
            if (!free.seats().isEmpty() || free.hasLeft() || free.isActingCommander()) {
                continue;
            }
            SimVehicle v = sim.vehicle(free.vehicle());
            for (Seat st : cdr.slots().all()) {
                if (st.role().equals(Mission.COMMANDER)) {
                    continue;
                }
                Optional<Seat> owner = cdr.slots().owner(st);
                boolean manageable = owner.isEmpty() || held.contains(owner.get());
                String h = holder.get(st);
                boolean open = h == null ? manageable
                        : byId.get(h).seats().size() > 1 && mission().role(st.role()).orElseThrow().isSecondary();
                if (open && mission().role(st.role()).orElseThrow().requirement().isMetBy(v.description())) {
                    return free.vehicle() + " is free and could take " + st
                            + (h == null ? ", which is vacant" : ", which " + h + " carries beside its own role");
                }
            }
        }
        return "";
    }

    /**
     * Whether the team is exactly as the planner would have it: settled, and when the planner gives
     * every role a vehicle of its own, so does the team.
     */
    public boolean matchesPlan() {
        if (!settled()) {
            return false;
        }
        Cell cdr = sim.commanders().get(0);
        if (!plan(cdr.vehicle()).optimalReached()) {
            return true;
        }
        return teams(sim.cells()).getOrDefault(cdr.vehicle(), List.of()).stream()
                .allMatch(c -> c.seats().size() == 1);
    }

    private Mission mission() {
        return sim.mission();
    }

    /** Seats of {@code role} whose owning seat is held: the most holders the tree can manage now. */
    private static int capacity(Cell cdr, String role, Set<Seat> held) {
        int n = 0;
        for (int slot = 0; slot < cdr.slots().optimal(role); slot++) {
            Optional<Seat> owner = cdr.slots().owner(new Seat(role, slot));
            if (owner.isEmpty() || held.contains(owner.get())) {
                n++;
            }
        }
        return n;
    }

    /** The planner's configuration for the live honest vehicles under {@code commander}. */
    public TeamConfiguration plan(String commander) {
        List<CapabilitySummary> live = new ArrayList<>();
        for (Cell c : sim.cells()) {
            if (!c.hasLeft()) {
                live.add(sim.vehicle(c.vehicle()).description().summary());
            }
        }
        return TeamPlanner.plan(sim.mission(), live, commander);
    }

    /** A loss profile within which the protocols' timing assumption (one-way latency below comTimeout) holds. */
    public static LinkProfile lossy(double loss) {
        return new LinkProfile(5, 20, loss, 0.05, 0.05, 30);
    }

    private void fail(String what) {
        List<String> lines = new ArrayList<>(sim.trace());
        lines.add("--- views at the violation");
        sim.cells().forEach(c -> lines.add(c.view().toJson()));
        throw new InvariantViolation(what, sim.seed(), sim.nowMillis(), lines);
    }
}
