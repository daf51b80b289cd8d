package net.smc.sim.team;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;

import net.smc.core.cell.CellEvent;
import net.smc.core.cell.MissionState;
import net.smc.core.cell.Missions;
import net.smc.core.message.MessageType;
import net.smc.core.transport.Address;
import net.smc.core.transport.sim.CpuModel;
import net.smc.core.transport.sim.LinkProfile;
import org.junit.jupiter.api.Test;

/**
 * The steady state's statuses: a parent answers each heartbeat with a status, and that answer is
 * the only status in a period; a child whose heartbeats go unanswered (lost) still gets a status of
 * the parent's own within a period and a half.
 */
class SteadyStateTrafficTest {
    private static final long PERIOD = 500;

    /** STATUS datagrams sent, by "from>to" address pair. */
    private final Map<String, Integer> statuses = new HashMap<>();
    private final List<CellEvent> events = new ArrayList<>();

    private TeamSimulation formedTeam(long seed) {
        TeamSimulation sim = TeamSimulation.builder(Missions.reconnaissance(), Missions.REPOSITORY, seed)
                .vehicles(SimVehicle.reconnaissance(2, 1, 2, 2)).listener(events::add).build();
        sim.network().setCpuModel(new CpuModel() {
            @Override
            public long sendMicros(Address at, Address to, byte[] data) {
                if (typeOf(data) == MessageType.STATUS.code()) {
                    statuses.merge(at + ">" + to, 1, Integer::sum);
                }
                return 0;
            }

            @Override
            public long receiveMicros(Address at, Address from, byte[] data, boolean broadcast) {
                return 0;
            }
        });
        sim.start();
        assertTrue(sim.runUntil(() -> sim.cell("cdr").missionState().equals(Optional.of(MissionState.OPTIMAL))
                && sim.invariants().settled(), 20_000), "the team settles");
        sim.run(2 * PERIOD);
        statuses.clear();
        return sim;
    }

    /** The frame's type byte, in a datagram sealed by the ideal authentication (an 8-byte counter first) or not. */
    private static int typeOf(byte[] data) {
        for (int at : new int[] {0, 8}) {
            if (data.length > at + 3 && data[at] == 'S' && data[at + 1] == 'M') {
                return data[at + 3] & 0xFF;
            }
        }
        return -1;
    }

    private int statusesTo(TeamSimulation sim, String parent, String child) {
        return statuses.getOrDefault(sim.address(parent) + ">" + sim.address(child), 0);
    }

    @Test
    void eachChildGetsOneStatusAPeriod() {
        TeamSimulation sim = formedTeam(51);
        sim.run(20 * PERIOD);
        for (String parent : List.of("cdr", "s1", "s2")) {
            for (String child : sim.cell(parent).children().keySet()) {
                int n = statusesTo(sim, parent, child);
                // One answer per heartbeat, twenty heartbeats (a period's jitter either way); two a
                // period (an answer and the tick's own) would be about forty.
                assertTrue(n >= 19 && n <= 21, parent + " sent " + n + " statuses to " + child + " in 20 periods");
            }
        }
    }

    @Test
    void aChildWhoseHeartbeatsAreLostStillHearsItsParent() {
        TeamSimulation sim = formedTeam(52);
        String child = sim.cell("cdr").children().keySet().iterator().next();
        sim.network().setLink(sim.address(child), sim.address("cdr"), LinkProfile.DEFAULT.withLoss(1.0));
        int failuresBefore = failures();
        sim.run(5 * PERIOD); // shorter than the failure timeout (six periods)
        int n = statusesTo(sim, "cdr", child);
        // Unanswered heartbeats: the tick sends a status when none went for a period and a half, so
        // two or three in five periods (none at all if only heartbeats were answered).
        assertTrue(n >= 2 && n <= 4, "cdr sent " + n + " statuses to " + child + " while its heartbeats were lost");
        sim.network().clearLinks();
        sim.run(4 * PERIOD);
        assertEquals(failuresBefore, failures(), "no failure declared");
        assertTrue(sim.cell("cdr").children().containsKey(child));
    }

    private int failures() {
        return (int) events.stream().filter(e -> e.kind() == CellEvent.Kind.FAILURE).count();
    }
}
