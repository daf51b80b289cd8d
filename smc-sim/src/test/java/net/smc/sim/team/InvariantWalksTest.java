package net.smc.sim.team;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import net.smc.core.cell.Cell;
import net.smc.core.cell.Missions;
import org.junit.jupiter.api.Test;

/**
 * The invariant checks of a real team walk the structural rules only when a cell's readings
 * changed: a settled team's checks mostly skip the walk, and a crash (a cell gone, its children's
 * leases dangling, then dropped) makes the next checks walk them again.
 */
class InvariantWalksTest {
    @Test
    void aSettledTeamIsWalkedOnlyWhenSomethingChanges() {
        TeamSimulation sim = TeamSimulation.builder(Missions.reconnaissance(), Missions.REPOSITORY, 11)
                .vehicles(SimVehicle.reconnaissance(3, 2, 2, 2)).security(TeamSimulation.Security.IDEAL).build();
        sim.start();
        assertTrue(sim.runUntil(() -> sim.invariants().settled(), 15_000), sim.invariants().unsettled());
        sim.run(2_000);
        TeamInvariants inv = sim.invariants();
        long checks = inv.checks();
        long walks = inv.structuralWalks();
        sim.run(5_000);
        assertEquals(100, inv.checks() - checks, "a check every 50 ms");
        assertTrue(inv.structuralWalks() - walks < 10, "a settled team is seldom walked: "
                + (inv.structuralWalks() - walks) + " walks in 100 checks");
        String manager = sim.cells().stream().filter(c -> !c.isActingCommander() && !c.children().isEmpty())
                .map(Cell::vehicle).findFirst().orElseThrow();
        long before = inv.structuralWalks();
        sim.crash(manager);
        sim.run(50);
        assertEquals(before + 1, inv.structuralWalks(), "the check after a crash walks the rules");
    }
}
