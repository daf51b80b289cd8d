package net.smc.sim.team;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;

import net.smc.core.cell.Missions;
import net.smc.core.message.DecodeResult;
import net.smc.core.message.MessageDecoder;
import net.smc.core.message.MessageType;
import net.smc.core.transport.Address;
import net.smc.core.transport.sim.NetworkObserver;
import org.junit.jupiter.api.Test;

/**
 * The cheap check before discovery's expensive first contact: a free vehicle answers a manager's
 * discovery only when it is able to hold one of the roles the manager's role manages.
 */
class DiscoveryFilterTest {

    /** Discovery replies on the wire, as "sender>receiver". */
    private static List<String> discoveryReplies(TeamSimulation sim) {
        List<String> replies = new ArrayList<>();
        MessageDecoder decoder = new MessageDecoder(sim::nowMillis);
        sim.network().addObserver(new NetworkObserver() {
            @Override
            public void delivered(long atMillis, Address from, Address to, byte[] data) {
                if (decoder.decode(data) instanceof DecodeResult.Decoded d && d.envelope().type() == MessageType.DISCOVERY_REPLY) {
                    replies.add(d.envelope().sender() + ">" + sim.vehicleAt(to).orElse("?"));
                }
            }
        });
        return replies;
    }

    private static TeamSimulation sim(List<SimVehicle> team) {
        return TeamSimulation.builder(Missions.reconnaissance(), Missions.REPOSITORY, 3)
                .security(TeamSimulation.Security.NONE).vehicles(team).build();
    }

    @Test
    void discovery_aVehicleAbleToHoldNoManagedRoleStaysQuiet() {
        // The commander manages surveyors and aggregators; a detector can hold neither.
        TeamSimulation sim = sim(List.of(SimVehicle.command("cdr").asCommander(), SimVehicle.detector("d1")));
        List<String> replies = discoveryReplies(sim);
        sim.start();
        sim.run(10_000);
        assertTrue(sim.cell("cdr").children().isEmpty(), () -> "children " + sim.cell("cdr").children());
        assertEquals(List.of(), replies.stream().filter(r -> r.startsWith("d1>")).toList());
        assertTrue(sim.cell("d1").seats().isEmpty());
    }

    @Test
    void discovery_aVehicleThatFitsAnswersAndIsGivenTheRole() {
        TeamSimulation sim = sim(List.of(SimVehicle.command("cdr").asCommander(), SimVehicle.surveyor("s1"),
                SimVehicle.detector("d1")));
        List<String> replies = discoveryReplies(sim);
        sim.start();
        // Until s1 has heard d1's acceptance too (d1 holds its seat a little before its manager knows).
        boolean seated = sim.runUntil(() -> !sim.cell("d1").seats().isEmpty() && !sim.cell("s1").seats().isEmpty()
                && sim.cell("s1").children().containsKey("d1"), 20_000);
        assertTrue(seated, () -> String.join("\n", sim.trace()));
        assertTrue(replies.contains("s1>cdr"), () -> "replies " + replies);
        assertTrue(replies.contains("d1>s1"), () -> "replies " + replies);
        assertTrue(replies.stream().noneMatch(r -> r.equals("d1>cdr")), () -> "replies " + replies);
        assertEquals(Set.of("d1"), Set.copyOf(sim.cell("s1").children().keySet()).stream()
                .filter(v -> v.equals("d1")).collect(java.util.stream.Collectors.toSet()));
    }
}
