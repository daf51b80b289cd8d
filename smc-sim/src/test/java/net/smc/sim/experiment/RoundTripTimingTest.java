package net.smc.sim.experiment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import net.smc.core.cell.CellEvent;
import net.smc.core.cell.Scheme;
import net.smc.core.cell.Timing;
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
 * The retransmission timeout and the discovery repeat follow the measured round trips, first
 * contacts included: a discovery reply names the discovery it answers, so a manager knows the round
 * trip to a vehicle before it assigns the vehicle a role, and repeats a discovery when its answers
 * should have come rather than after the fixed first timeout (100 ms here; round trips 6-10 ms).
 */
class RoundTripTimingTest {
    private static final int ROLES = 10;

    @TempDir
    Path dir;

    /** The mission's timing: comTimeout 500 ms, failureTimeout 3000 ms. */
    private static final Timing TIMING = new Timing(500, 3_000, 1);

    private GeneratedMission generated() throws Exception {
        return MissionGenerator.write(TreeShape.of(ROLES, 4), dir, Project.bootEvents());
    }

    private TeamSimulation team(GeneratedMission g, long seed, List<CellEvent> events, Map<String, Long> firstTimeouts)
            throws Exception {
        Mission mission = new MissionLoader(new PolicyRepository(g.repository())).load(g.instanceFile(Scheme.DISTRIBUTED));
        TeamSimulation[] sim = new TeamSimulation[1];
        sim[0] = TeamSimulation.builder(mission, new PolicyRepository(g.repository()), seed)
                .vehicles(g.vehicles()).scheme(Scheme.DISTRIBUTED).link(LinkProfile.fixed(3).withLatency(3, 2))
                .listener(e -> {
                    events.add(e);
                    if (e.kind() == CellEvent.Kind.ASSIGNING) {
                        // The timeout the assignment about to go gets: nothing critical went to the vehicle before.
                        String vehicle = e.detail().substring(e.detail().lastIndexOf(" to ") + 4);
                        firstTimeouts.putIfAbsent(e.vehicle() + "->" + vehicle, sim[0].cell(e.vehicle()).communication()
                                .sender().firstTimeoutMillis(sim[0].address(vehicle)));
                    }
                }).build();
        return sim[0];
    }

    private static String commander(List<CellEvent> events) {
        return events.stream().filter(e -> e.kind() == CellEvent.Kind.COMMANDING).map(CellEvent::vehicle).findFirst().orElseThrow();
    }

    @Test
    void everyFirstAssignmentIsTimedByMeasuredRoundTrips_theDiscoveryRepliesFirstOfAll() throws Exception {
        List<CellEvent> events = new ArrayList<>();
        Map<String, Long> firstTimeouts = new HashMap<>();
        TeamSimulation sim = team(generated(), 5, events, firstTimeouts);
        sim.start();
        assertTrue(sim.runUntil(() -> events.stream().filter(e -> e.kind() == CellEvent.Kind.ACCEPTED).count() == ROLES - 1,
                10_000), () -> String.join("\n", sim.trace()));
        assertEquals(100, TIMING.senderSettings().initialTimeoutMillis());
        // One first assignment a seat, and one more for each vehicle two managers of a level both chose.
        assertTrue(firstTimeouts.size() >= ROLES - 1, () -> "assignments: " + firstTimeouts);
        // A first sample r gives r + 4 r / 2 = 3 r, at most 30 ms for round trips of 6-10 ms: the minimum, 50 ms, applies.
        assertEquals(50, TIMING.minRetransmissionMillis());
        firstTimeouts.forEach((pair, timeout) -> assertEquals(TIMING.minRetransmissionMillis(), timeout,
                () -> pair + ": the first assignment waits " + timeout + " ms for its Ack"));
    }

    /**
     * Seeds 6-8 (the commander's first tick, at a random phase of its 500 ms period, comes later
     * than the repeat in each): the repeat is no sooner than the minimum timeout and not the fixed
     * first timeout (100 ms) after the first discovery.
     */
    @Test
    void aCommanderWhoseVehicleMissedItsDiscoveryDiscoversAgainWhenTheOthersAnswersShowItShouldHaveAnswered()
            throws Exception {
        GeneratedMission g = generated();
        String lost = g.roles().stream().filter(r -> r.level() == 1).findFirst().orElseThrow().vehicle(0);
        long minimum = TIMING.minRetransmissionMillis();
        for (long seed = 6; seed <= 8; seed++) {
            List<CellEvent> events = new ArrayList<>();
            TeamSimulation sim = team(g, seed, events, new HashMap<>());
            Address lostAt = sim.address(lost);
            // The first discovery's copy to one level-1 vehicle, and nothing else, is lost.
            sim.network().setRadio((from, to) -> sim.nowMillis() > 2 || !to.equals(lostAt));
            Discoveries discoveries = new Discoveries();
            sim.network().addObserver(discoveries);
            sim.start();
            sim.run(150);
            String commander = commander(events);
            List<Long> sent = discoveries.sent.getOrDefault(sim.address(commander), List.of());
            String where = "seed " + seed + ": the commander discovered at " + sent + "\n" + String.join("\n", sim.trace());
            assertTrue(sent.size() >= 2, where);
            long repeat = sent.get(1) - sent.get(0);
            assertTrue(repeat >= minimum && repeat < minimum + 10, () -> "again after " + repeat + " ms; " + where);
            long assigned = events.stream().filter(e -> e.vehicle().equals(commander) && e.kind() == CellEvent.Kind.ASSIGNING
                    && e.detail().endsWith(" to " + lost)).mapToLong(CellEvent::timeMillis).findFirst().orElse(-1);
            assertTrue(assigned > 0 && assigned < minimum + 25, () -> lost + "'s seat given at " + assigned + " ms; " + where);
        }
    }

    /** When each cell broadcast a discovery, by its address. */
    private static final class Discoveries implements NetworkObserver {
        final CpuCharge parse = new CpuCharge(CpuCosts.ZERO, "m", v -> 0, (v, u) -> false, IdealAuthentication.PAYLOAD_OFFSET);
        final Map<Address, List<Long>> sent = new HashMap<>();

        @Override
        public void sent(long atMillis, Address from, Address to, byte[] data) {
            if (to == null && parse.type(data) == MessageType.DISCOVERY.code()) {
                sent.computeIfAbsent(from, a -> new ArrayList<>()).add(atMillis);
            }
        }
    }
}
