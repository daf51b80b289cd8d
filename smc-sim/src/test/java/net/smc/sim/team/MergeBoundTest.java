package net.smc.sim.team;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

import net.smc.core.cell.Cell;
import net.smc.core.cell.Missions;
import org.junit.jupiter.api.Test;

/**
 * The invariant on acting commanders: two that cannot hear each other (in different parts of a
 * partitioned network) may both act as long as the parts stay apart; two that can hear each other
 * may not stay so beyond the merge bound, and the check says so, naming both.
 */
class MergeBoundTest {
    private static final long FAILURE = 3_000;

    @Test
    void twoCommandersApartAreFineAndTwoThatHearEachOtherBeyondTheBoundAreAViolation() {
        TeamSimulation sim = TeamSimulation.builder(Missions.reconnaissance(), Missions.REPOSITORY, 7)
                .vehicles(SimVehicle.reconnaissance(3, 2, 2, 2)).security(TeamSimulation.Security.IDEAL)
                .mergeBound(1).build();
        sim.start();
        assertTrue(sim.runUntil(() -> sim.invariants().settled(), 15_000), sim.invariants().unsettled());
        sim.run(3_000);
        String backup = sim.cells().stream().filter(c -> !c.isActingCommander() && c.parent().equals(Optional.of("cdr"))
                && c.seats().get(0).role().equals("surveyor")).map(Cell::vehicle).findFirst().orElseThrow();
        List<String> side = new ArrayList<>(List.of(backup, "a2", "s3"));
        sim.cells().stream().filter(c -> c.parent().equals(Optional.of(backup))).forEach(c -> side.add(c.vehicle()));
        sim.partition(side);
        assertTrue(sim.runUntil(() -> sim.commanders().size() == 2, 4 * FAILURE), "a commander in each part");
        sim.run(2 * FAILURE);   // checked after every step: apart, two commanders break nothing
        assertEquals(2, sim.commanders().size());
        sim.heal();
        InvariantViolation v = assertThrows(InvariantViolation.class, () -> sim.run(FAILURE),
                "two commanders heard each other beyond a merge bound of 1 ms");
        assertTrue(v.getMessage().contains("have heard each other"), v.getMessage());
        assertTrue(v.getMessage().contains("cdr") && v.getMessage().contains(backup), v.getMessage());
    }
}
