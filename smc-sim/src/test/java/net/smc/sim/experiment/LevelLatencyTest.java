package net.smc.sim.experiment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import net.smc.core.cell.CellEvent;
import net.smc.core.cell.Scheme;
import net.smc.core.message.MessageType;
import net.smc.core.mission.Mission;
import net.smc.core.mission.MissionLoader;
import net.smc.core.security.IdealAuthentication;
import net.smc.core.transport.Address;
import net.smc.core.transport.sim.LinkProfile;
import net.smc.core.transport.sim.NetworkObserver;
import net.smc.policy.api.PolicyRepository;
import net.smc.sim.team.TeamSimulation;

/**
 * What one level of the management tree costs in round trips: a manager gives a seat from the
 * capability summary of the discovery reply (no capability request), sends the role's own policy
 * files behind the assignment (the vehicle asks for none), and repeats discovery early when its
 * replies were lost (not a heartbeat period later).
 */
class LevelLatencyTest {
    private static final int ROLES = 20;

    @TempDir
    Path dir;

    /** Datagrams delivered, by sending vehicle and message type. */
    private static final class Counts implements NetworkObserver {
        final CpuCharge parse = new CpuCharge(CpuCosts.ZERO, v -> 0, (v, u) -> false, IdealAuthentication.PAYLOAD_OFFSET);
        final Map<String, Map<MessageType, Integer>> bySender = new HashMap<>();

        @Override
        public void delivered(long atMillis, Address from, Address to, byte[] data) {
            int type = parse.type(data);
            if (type >= 0) {
                bySender.computeIfAbsent(parse.sender(data), v -> new HashMap<>())
                        .merge(MessageType.fromCode(type), 1, Integer::sum);
            }
        }

        int of(MessageType type) {
            return bySender.values().stream().mapToInt(m -> m.getOrDefault(type, 0)).sum();
        }

        int of(String vehicle, MessageType type) {
            return bySender.getOrDefault(vehicle, Map.of()).getOrDefault(type, 0);
        }
    }

    private GeneratedMission generated() throws Exception {
        return MissionGenerator.write(TreeShape.of(ROLES, 4), dir, Project.bootEvents());
    }

    private TeamSimulation team(GeneratedMission g, List<CellEvent> events, LinkProfile link) throws Exception {
        Mission mission = new MissionLoader(new PolicyRepository(g.repository())).load(g.instanceFile(Scheme.DISTRIBUTED));
        return TeamSimulation.builder(mission, new PolicyRepository(g.repository()), 11)
                .vehicles(g.vehicles()).scheme(Scheme.DISTRIBUTED).link(link).listener(events::add).build();
    }

    private static Set<String> started(List<CellEvent> events) {
        Set<String> vehicles = new HashSet<>();
        events.stream().filter(e -> e.kind() == CellEvent.Kind.ACCEPTED).forEach(e -> vehicles.add(e.vehicle()));
        return vehicles;
    }

    /**
     * On a network that loses nothing, the team forms with no capability request at all, and no
     * leaf (whose role manages none, so it fetches no file for children) asks for a policy file:
     * its role's files came behind its assignment.
     */
    @Test
    void noCapabilityRequestAndNoPolicyRequestForARolesOwnFiles() throws Exception {
        GeneratedMission g = generated();
        List<CellEvent> events = new ArrayList<>();
        TeamSimulation sim = team(g, events, LinkProfile.fixed(3).withLatency(3, 2));
        Counts counts = new Counts();
        sim.network().addObserver(counts);
        sim.start();
        assertTrue(sim.runUntil(() -> started(events).size() == ROLES - 1, 10_000), () -> String.join("\n", sim.trace()));
        assertEquals(0, counts.of(MessageType.CAPABILITY_REQUEST), () -> "capability requests: " + counts.bySender);
        assertTrue(counts.of(MessageType.ROLE_ASSIGNMENT) >= ROLES - 1);
        List<String> leaves = g.roles().stream().filter(r -> r.level() == 3).flatMap(r -> java.util.stream.IntStream
                .range(0, r.seats()).mapToObj(r::vehicle)).toList();
        assertTrue(!leaves.isEmpty());
        for (String leaf : leaves) {
            assertEquals(0, counts.of(leaf, MessageType.POLICY_REQUEST), () -> leaf + " asked for policy files: " + counts.bySender);
            assertTrue(counts.of(leaf, MessageType.ASSIGNMENT_RESPONSE) >= 1, () -> leaf + " never answered an assignment");
        }
    }

    /**
     * Every leaf's discovery replies are lost until 110 ms, when every manager of the leaves (each
     * started about 30 ms in, on this fast network) has discovered once: each discovers again at the
     * first retransmission timeout (100 ms) of its start, so every leaf is started by 300 ms, a
     * rediscovery after a lost race for a vehicle included. Waiting for each manager's tick (every
     * 500 ms, each at its own phase) left most leaves unstarted then.
     */
    @Test
    void aManagerWhoseDiscoveryRepliesWereLostDiscoversAgainBeforeItsTick() throws Exception {
        GeneratedMission g = generated();
        List<CellEvent> events = new ArrayList<>();
        TeamSimulation sim = team(g, events, LinkProfile.fixed(3).withLatency(3, 2));
        Set<String> leaves = new HashSet<>();
        g.roles().stream().filter(r -> r.level() == 3).forEach(r -> {
            for (int i = 0; i < r.seats(); i++) {
                leaves.add(r.vehicle(i));
            }
        });
        Set<Address> leafAddresses = new HashSet<>();
        leaves.forEach(v -> leafAddresses.add(sim.address(v)));
        sim.network().setRadio((from, to) -> sim.nowMillis() >= 110 || !leafAddresses.contains(from));
        sim.start();
        sim.run(300);
        long managersDiscovering = events.stream().filter(e -> e.kind() == CellEvent.Kind.DISCOVERING && e.timeMillis() < 110
                && g.roles().stream().anyMatch(r -> r.level() == 2 && e.vehicle().startsWith(r.name() + "n"))).count();
        assertTrue(managersDiscovering >= 2, () -> "level-2 managers discovering before 110 ms: " + managersDiscovering + "\n"
                + String.join("\n", sim.trace()));
        Set<String> unstarted = new HashSet<>(leaves);
        unstarted.removeAll(started(events));
        assertTrue(unstarted.isEmpty(), () -> "leaves not started by 300 ms: " + unstarted + "\n" + String.join("\n", sim.trace()));
    }
}
