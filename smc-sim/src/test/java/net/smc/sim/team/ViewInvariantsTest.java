package net.smc.sim.team;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.TreeMap;

import net.smc.core.capability.CapabilityDescription;
import net.smc.core.cell.CellView;
import net.smc.core.cell.MissionState;
import net.smc.core.cell.Missions;
import org.junit.jupiter.api.Test;

/** The view-based safety rules and settling goal that {@link TeamOverUdpTest} checks at every poll. */
class ViewInvariantsTest {
    private static final Map<String, CapabilityDescription> VEHICLES = new TreeMap<>();

    static {
        SimVehicle.reconnaissance(2, 1, 2, 2).forEach(v -> VEHICLES.put(v.id(), v.description()));
    }

    private static CellView view(String vehicle, String parent, boolean acting, boolean suspended, String... seats) {
        return new CellView(vehicle, "HouseSurvey", null, 0, acting ? vehicle : parent, acting, parent, suspended,
                Arrays.asList(seats), Map.of(), acting ? MissionState.OPTIMAL : null, Map.of(), 0);
    }

    private static Map<String, CellView> views(CellView... views) {
        Map<String, CellView> m = new TreeMap<>();
        for (CellView v : views) {
            m.put(v.vehicle(), v);
        }
        return m;
    }

    private static Optional<String> violation(Map<String, CellView> views) {
        return ViewInvariants.violation(views, Missions.reconnaissance(), VEHICLES);
    }

    @Test
    void violation_aSeatHeldTwiceInOneTeam() {
        Map<String, CellView> v = views(view("cdr", null, true, false, "commander#0"),
                view("s1", "cdr", false, false, "surveyor#0"), view("s2", "cdr", false, false, "surveyor#0"));

        assertEquals(Optional.of("seat surveyor#0 has two holders in the team of cdr: s1 and s2"), violation(v));
    }

    @Test
    void violation_noneWhenTheOtherHolderIsSuspended() {
        Map<String, CellView> v = views(view("cdr", null, true, false, "commander#0"),
                view("s1", "cdr", false, true, "surveyor#0"), view("s2", "cdr", false, false, "surveyor#0"));

        assertEquals(Optional.empty(), violation(v));
    }

    @Test
    void violation_noneForOneSeatInTwoTeams() {
        Map<String, CellView> v = views(view("cdr", null, true, false, "commander#0"),
                view("s1", null, true, false, "commander#0"), view("d1", "cdr", false, false, "hdetector#0"),
                view("d2", "s1", false, false, "hdetector#0"));

        assertEquals(Optional.empty(), violation(v));
    }

    @Test
    void violation_aHolderThatLacksTheRolesRequirement() {
        Map<String, CellView> v = views(view("cdr", null, true, false, "commander#0"),
                view("d1", "cdr", false, false, "surveyor#0"));

        assertTrue(violation(v).orElseThrow().startsWith("d1 holds surveyor#0 but lacks"), violation(v).toString());
    }

    @Test
    void violation_aSlotBeyondTheOptimalCardinality() {
        Map<String, CellView> v = views(view("cdr", null, true, false, "commander#0"),
                view("s1", "cdr", false, false, "surveyor#2"));

        assertEquals(Optional.of("s1 holds surveyor#2 beyond the optimal cardinality 2"), violation(v));
    }

    @Test
    void violation_aCycleOfParents() {
        Map<String, CellView> v = views(view("s1", "s2", false, false), view("s2", "s1", false, false));

        assertTrue(violation(v).orElseThrow().startsWith("the parent relation has a cycle"), violation(v).toString());
    }

    /** s2 is free; the held surveyor seat can manage one detector and one relay, which s1 may host itself. */
    @Test
    void unsettled_namesTheMissingHolders() {
        Map<String, CellView> v = views(view("cdr", null, true, false, "commander#0"),
                view("s1", "cdr", false, false, "surveyor#0"), view("s2", null, false, false),
                view("a1", "cdr", false, false, "aggregator#0"));

        assertEquals("holders {commander=1, surveyor=1, aggregator=1, hdetector=0, relay=0}, the running vehicles allow "
                        + "{commander=1, surveyor=2, aggregator=1, hdetector=1, relay=1}",
                ViewInvariants.unsettled(v, Missions.reconnaissance(), VEHICLES));
    }

    @Test
    void unsettled_emptyForTheTreeOfFigureFive() {
        Map<String, CellView> v = views(view("cdr", null, true, false, "commander#0"),
                view("s1", "cdr", false, false, "surveyor#0"), view("s2", "cdr", false, false, "surveyor#1"),
                view("a1", "cdr", false, false, "aggregator#0"), view("d1", "s1", false, false, "hdetector#0"),
                view("r1", "s1", false, false, "relay#0"), view("d2", "s2", false, false, "hdetector#1"),
                view("r2", "s2", false, false, "relay#1"));

        assertEquals("", ViewInvariants.unsettled(v, Missions.reconnaissance(), VEHICLES));
        assertEquals(List.of("cdr"), UdpTeam.commanders(v));
    }
}
