package net.smc.sim.experiment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.HashMap;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import net.smc.core.cell.Scheme;
import net.smc.core.message.MessageType;
import net.smc.core.mission.Mission;
import net.smc.core.mission.MissionLoader;
import net.smc.core.security.IdealAuthentication;
import net.smc.core.transport.Address;
import net.smc.core.transport.sim.NetworkObserver;
import net.smc.policy.api.PolicyRepository;
import net.smc.sim.team.TeamSimulation;

/**
 * A cell drops, before checking it, a discovery it would not answer (it has a parent, or could
 * hold no role that manager manages): in a large team most of the discoveries every cell hears.
 * It must never drop one it answers, and a seated manager, which answers none, verifies none.
 */
class UnverifiedDiscoveryTest {
    private static final int TYPE_AT = IdealAuthentication.PAYLOAD_OFFSET + 3;

    @TempDir
    Path dir;

    @Test
    void everyDiscoveryACellAnswersWasCheckedAndMostOthersWereNot() throws Exception {
        GeneratedMission g = MissionGenerator.write(TreeShape.of(50, 4), dir, Project.bootEvents());
        Mission mission = new MissionLoader(new PolicyRepository(g.repository())).load(g.instanceFile(Scheme.DISTRIBUTED));
        TeamSimulation sim = TeamSimulation.builder(mission, new PolicyRepository(g.repository()), 7)
                .vehicles(g.vehicles()).scheme(Scheme.DISTRIBUTED).build();
        IdealAuthentication auth = sim.idealAuthentication();
        Map<String, Integer> checkedDiscoveries = new HashMap<>();   // "manager>receiver"
        Map<String, Integer> replies = new HashMap<>();              // "manager>receiver", delivered
        int[] dropped = {0};
        int[] all = {0};
        sim.network().addObserver(new NetworkObserver() {
            @Override
            public void delivered(long atMillis, Address from, Address to, byte[] data) {
                int type = data.length > TYPE_AT ? data[TYPE_AT] & 0xFF : -1;
                if (type == MessageType.DISCOVERY.code()) {
                    all[0]++;
                    // Asked just before the endpoint gets it: what the endpoint is about to do.
                    if (auth.dropsUnverified(to, data)) {
                        dropped[0]++;
                    } else {
                        checkedDiscoveries.merge(from + ">" + to, 1, Integer::sum);
                    }
                } else if (type == MessageType.DISCOVERY_REPLY.code()) {
                    replies.merge(to + ">" + from, 1, Integer::sum);
                }
            }
        });
        sim.start();
        assertTrue(sim.runUntil(() -> sim.cells().stream().allMatch(c -> c.isActingCommander() || c.seats().size() > 0), 30_000),
                "the team formed");

        assertTrue(!replies.isEmpty(), "vehicles answered discovery");
        replies.forEach((pair, n) -> assertTrue(n <= checkedDiscoveries.getOrDefault(pair, 0),
                () -> pair + ": " + n + " replies to " + checkedDiscoveries.getOrDefault(pair, 0) + " discoveries checked"));
        assertEquals(dropped[0], auth.ignoredUnverified(), "the endpoints dropped what they were asked about");
        assertTrue(dropped[0] > all[0] / 2, () -> dropped[0] + " of " + all[0] + " discoveries dropped unchecked");
    }
}
