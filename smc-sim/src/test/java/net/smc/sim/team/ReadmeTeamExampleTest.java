package net.smc.sim.team;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;

import net.smc.core.cell.Missions;
import net.smc.core.mission.Mission;
import net.smc.policy.api.PolicyRepository;
import org.junit.jupiter.api.Test;

/** The README's "Teams of cells" example, as written there. */
class ReadmeTeamExampleTest {

    @Test
    void theExampleRuns() {
        Mission mission = Missions.reconnaissance();
        Path policies = Path.of(System.getProperty("smc.repo.dir", "../policies"));
        // From README.md:
        TeamSimulation sim = TeamSimulation.builder(mission, new PolicyRepository(policies), 7)
                .vehicles(SimVehicle.reconnaissance(2, 1, 2, 2)).build();   // commander "cdr" + 7 vehicles
        sim.start();
        assertTrue(sim.runUntil(() -> sim.invariants().settled(), 30_000));
        sim.crash("s1");                                                   // a surveyor fails ...
        assertTrue(sim.runUntil(() -> sim.invariants().settled(), 30_000)); // ... and its role is re-assigned
        assertTrue(sim.cells().stream().anyMatch(c -> !c.vehicle().equals("s1")
                && c.seats().stream().anyMatch(s -> s.role().equals("surveyor"))));
    }
}
