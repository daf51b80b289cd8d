package net.smc.sim.team;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Optional;

import org.junit.jupiter.api.Test;

import net.smc.core.cell.Cell;
import net.smc.core.cell.MissionState;
import net.smc.core.cell.Missions;

class TeamFormationTest {

    private static TeamSimulation sim(long seed, int s, int a, int d, int r) {
        return TeamSimulation.builder(Missions.reconnaissance(), Missions.REPOSITORY, seed)
                .vehicles(SimVehicle.reconnaissance(s, a, d, r)).build();
    }

    @Test
    void theReconnaissanceTeamFormsTheTreeOfFigureFive() {
        TeamSimulation sim = sim(1, 2, 1, 2, 2);
        sim.start();
        try {
            boolean settled = sim.runUntil(() -> sim.invariants().settled()
                    && sim.cell("cdr").missionState().equals(Optional.of(MissionState.OPTIMAL)), 30_000);
            assertTrue(settled, () -> sim.invariants().unsettled() + "\n" + String.join("\n", sim.trace()));
        } catch (InvariantViolation v) {
            throw new AssertionError(v.report(), v);
        }
        Cell cdr = sim.cell("cdr");
        assertEquals(java.util.Set.of("s1", "s2", "a1"), cdr.children().keySet());
        for (String s : new String[] {"s1", "s2"}) {
            assertEquals(2, sim.cell(s).children().size(), s + " manages a detector and a relay");
        }
    }
}
