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
 * A manager takes its role once its own policy files are in; the files of its children's roles come
 * behind its assignment, and those of the roles further down it fetches afterwards. A file its
 * manager is still fetching reaches a child when it arrives: the manager sends it on then (a request
 * for it is parked, not refused: a refusal would leave the child waiting for a failure timeout).
 */
class SubtreePoliciesTest {
    @TempDir
    Path dir;

    @Test
    void aFileItsManagerIsStillFetchingReachesAChildWhenItArrives() throws Exception {
        GeneratedMission g = MissionGenerator.write(TreeShape.of(5, 4), dir, Project.bootEvents());
        Mission mission = new MissionLoader(new PolicyRepository(g.repository())).load(g.instanceFile(Scheme.DISTRIBUTED));
        RoleType top = g.roles().stream().filter(r -> r.level() == 1).findFirst().orElseThrow();
        RoleType middle = g.managedBy(top.name(), Scheme.DISTRIBUTED).get(0);
        RoleType leaf = g.managedBy(middle.name(), Scheme.DISTRIBUTED).get(0);
        String manager = top.vehicle(0);
        String grandchild = leaf.vehicle(0);
        List<CellEvent> events = new ArrayList<>();
        TeamSimulation sim = TeamSimulation.builder(mission, new PolicyRepository(g.repository()), 7)
                .vehicles(g.vehicles()).scheme(Scheme.DISTRIBUTED).listener(events::add).build();
        // What the commander and the level-1 manager send each other takes 300 ms on the way: the
        // leaves' files, which the manager asks for once it has started, reach it 600 ms after that,
        // long after its child took its role and assigned the leaf's.
        sim.network().setLink(sim.address(GeneratedMission.COMMANDER), sim.address(manager), LinkProfile.fixed(300));
        sim.network().setLink(sim.address(manager), sim.address(GeneratedMission.COMMANDER), LinkProfile.fixed(300));
        sim.start();
        assertTrue(sim.runUntil(() -> accepted(events, grandchild) >= 0, 20_000), () -> String.join("\n", sim.trace()));
        long managerStarted = accepted(events, manager);
        long leafStarted = accepted(events, grandchild);
        assertTrue(events.stream().noneMatch(e -> e.kind() == CellEvent.Kind.REJECTED && e.detail().contains("not held")),
                () -> "a policy request was refused:\n" + String.join("\n", sim.trace()));
        assertTrue(events.stream().noneMatch(e -> e.kind() == CellEvent.Kind.REFUSED),
                () -> "a role was refused:\n" + String.join("\n", sim.trace()));
        assertTrue(leafStarted - managerStarted >= 550 && leafStarted - managerStarted < 1_000,
                () -> "manager started at " + managerStarted + " ms, the leaf below its child at " + leafStarted + " ms");
    }

    private static long accepted(List<CellEvent> events, String vehicle) {
        return events.stream().filter(e -> e.kind() == CellEvent.Kind.ACCEPTED && e.vehicle().equals(vehicle))
                .mapToLong(CellEvent::timeMillis).findFirst().orElse(-1);
    }
}
