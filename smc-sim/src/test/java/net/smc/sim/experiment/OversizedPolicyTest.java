package net.smc.sim.experiment;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import net.smc.core.cell.CellEvent;
import net.smc.core.cell.Scheme;
import net.smc.core.message.WireFormat;
import net.smc.core.mission.Mission;
import net.smc.core.mission.MissionLoader;
import net.smc.policy.api.PolicyRepository;
import net.smc.sim.team.TeamSimulation;

/**
 * A mission's loader refuses a policy file longer than a policy reply carries, but a commander reads
 * its repository while the mission runs: a file grown past the limit after the mission was loaded is
 * not sent, and the vehicle's request for it is refused, named, instead of throwing out of the
 * commander's handler. The vehicle then refuses the role, as for any file that does not come.
 */
class OversizedPolicyTest {
    @TempDir
    Path dir;

    @Test
    void aFileGrownPastTheLimitAfterLoading_isRefusedNamed_andTheVehicleRefusesTheRole() throws Exception {
        GeneratedMission g = MissionGenerator.write(TreeShape.of(5, 4), dir, Project.bootEvents());
        Mission mission = new MissionLoader(new PolicyRepository(g.repository())).load(g.instanceFile(Scheme.DISTRIBUTED));
        RoleType top = g.roles().stream().filter(r -> r.level() == 1).findFirst().orElseThrow();
        Path file = g.repository().resolve("roles/" + top.name() + "/mission.p2");
        String grown = Files.readString(file) + "// padding\n".repeat(WireFormat.MAX_POLICY_TEXT / 11 + 1);
        Files.writeString(file, grown);
        List<CellEvent> events = new ArrayList<>();
        TeamSimulation sim = TeamSimulation.builder(mission, new PolicyRepository(g.repository()), 7)
                .vehicles(g.vehicles()).scheme(Scheme.DISTRIBUTED).listener(events::add).build();
        sim.start();
        String vehicle = top.vehicle(0);
        sim.runUntil(() -> events.stream().anyMatch(e -> e.kind() == CellEvent.Kind.REFUSED && e.vehicle().equals(vehicle)),
                20_000);
        assertTrue(events.stream().anyMatch(e -> e.kind() == CellEvent.Kind.REJECTED
                        && e.vehicle().equals(GeneratedMission.COMMANDER)
                        && e.detail().contains("policy policy:/roles/" + top.name() + "/mission is " + grown.length()
                                + " bytes of text; a policy reply carries at most " + WireFormat.MAX_POLICY_TEXT)),
                () -> "no refusal naming the file:\n" + String.join("\n", sim.trace()));
        assertTrue(events.stream().anyMatch(e -> e.kind() == CellEvent.Kind.REFUSED && e.vehicle().equals(vehicle)
                        && e.detail().contains("its policies did not arrive")),
                () -> "the vehicle did not refuse the role:\n" + String.join("\n", sim.trace()));
    }
}
