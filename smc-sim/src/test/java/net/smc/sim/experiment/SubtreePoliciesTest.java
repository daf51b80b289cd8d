package net.smc.sim.experiment;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import net.smc.core.cell.CellEvent;
import net.smc.core.cell.Scheme;
import net.smc.core.mission.Mission;
import net.smc.core.mission.MissionLoader;
import net.smc.core.transport.sim.LinkProfile;
import net.smc.policy.api.PolicyRepository;
import net.smc.sim.team.TeamSimulation;

/**
 * A manager takes its role once its own policy files are in and fetches the files of the roles
 * below it afterwards; a child that asks it for one of those before it has arrived is answered when
 * it arrives, not refused (a refusal would leave the child waiting for a failure timeout).
 */
class SubtreePoliciesTest {
    @TempDir
    Path dir;

    @Test
    void aChildsRequestForAFileItsManagerIsStillFetchingIsAnsweredWhenItArrives() throws Exception {
        GeneratedMission g = MissionGenerator.write(TreeShape.of(5, 4), dir, Project.bootEvents());
        Mission mission = new MissionLoader(new PolicyRepository(g.repository())).load(g.instanceFile(Scheme.DISTRIBUTED));
        RoleType top = g.roles().stream().filter(r -> r.level() == 1).findFirst().orElseThrow();
        RoleType below = g.managedBy(top.name(), Scheme.DISTRIBUTED).get(0);
        String manager = top.vehicle(0);
        String child = below.vehicle(0);
        List<CellEvent> events = new ArrayList<>();
        TeamSimulation sim = TeamSimulation.builder(mission, new PolicyRepository(g.repository()), 7)
                .vehicles(g.vehicles()).scheme(Scheme.DISTRIBUTED).listener(events::add).build();
        // What the commander sends the level-1 manager takes 300 ms on the way: the files of the roles
        // below it reach it 300 ms after it took its role, long after its child asked it for them.
        sim.network().setLink(sim.address(GeneratedMission.COMMANDER), sim.address(manager), LinkProfile.fixed(300));
        sim.start();
        assertTrue(sim.runUntil(() -> accepted(events, child) >= 0, 20_000), () -> String.join("\n", sim.trace()));
        long managerStarted = accepted(events, manager);
        long childStarted = accepted(events, child);
        assertTrue(events.stream().noneMatch(e -> e.kind() == CellEvent.Kind.REJECTED && e.detail().contains("not held")),
                () -> "a policy request was refused:\n" + String.join("\n", sim.trace()));
        assertTrue(childStarted - managerStarted >= 250 && childStarted - managerStarted < 600,
                () -> "manager started at " + managerStarted + " ms, its child at " + childStarted + " ms");
    }

    private static long accepted(List<CellEvent> events, String vehicle) {
        return events.stream().filter(e -> e.kind() == CellEvent.Kind.ACCEPTED && e.vehicle().equals(vehicle))
                .mapToLong(CellEvent::timeMillis).findFirst().orElse(-1);
    }
}
