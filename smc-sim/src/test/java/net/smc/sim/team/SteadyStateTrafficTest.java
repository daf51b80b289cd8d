package net.smc.sim.team;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.TreeMap;

import net.smc.core.cell.CellEvent;
import net.smc.core.cell.MissionState;
import net.smc.core.cell.Missions;
import net.smc.core.message.MessageType;
import net.smc.core.transport.Address;
import net.smc.core.transport.sim.CpuModel;
import net.smc.core.transport.sim.LinkProfile;
import org.junit.jupiter.api.Test;

/**
 * The steady state's traffic: a parent answers each heartbeat, and that answer is the only one in
 * a period; while the child holds the parent's current status the answer is a bare ECHO, and a
 * status that changed goes in full until a heartbeat of the child names its version (so a lost one
 * is sent again); a child whose heartbeats go unanswered (lost) still hears its parent within a
 * period and a half; a subtree report that did not change goes once every sixteen heartbeats.
 */
class SteadyStateTrafficTest {
    private static final long PERIOD = 500;

    /** One datagram sent: when, from and to which address, its frame type. */
    private record Sent(long atMillis, Address from, Address to, int type) {
    }

    private final List<Sent> sent = new ArrayList<>();
    private final List<CellEvent> events = new ArrayList<>();

    private TeamSimulation formedTeam(long seed) {
        TeamSimulation sim = TeamSimulation.builder(Missions.reconnaissance(), Missions.REPOSITORY, seed)
                .vehicles(SimVehicle.reconnaissance(2, 1, 2, 2)).listener(events::add).build();
        sim.network().setCpuModel(new CpuModel() {
            @Override
            public long sendMicros(Address at, Address to, byte[] data) {
                sent.add(new Sent(sim.nowMillis(), at, to, typeOf(data)));
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
        sent.clear();
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

    /** The datagrams of {@code types} sent from {@code from} to {@code to} since {@code sinceMillis}, in order. */
    private List<Sent> sent(TeamSimulation sim, String from, String to, long sinceMillis, MessageType... types) {
        List<Sent> out = new ArrayList<>();
        for (Sent s : sent) {
            if (s.atMillis >= sinceMillis && sim.address(from).equals(s.from) && sim.address(to).equals(s.to)) {
                for (MessageType t : types) {
                    if (s.type == t.code()) {
                        out.add(s);
                    }
                }
            }
        }
        return out;
    }

    private int answers(TeamSimulation sim, String parent, String child) {
        return sent(sim, parent, child, 0, MessageType.STATUS, MessageType.ECHO).size();
    }

    @Test
    void eachChildGetsOneAnswerAPeriod_anEchoWhileNothingChanges() {
        TeamSimulation sim = formedTeam(51);
        sim.run(20 * PERIOD);
        for (String parent : List.of("cdr", "s1", "s2")) {
            for (String child : sim.cell(parent).children().keySet()) {
                int n = answers(sim, parent, child);
                // One answer per heartbeat, twenty heartbeats (a period's jitter either way); two a
                // period (an answer and the tick's own) would be about forty.
                assertTrue(n >= 19 && n <= 21, parent + " answered " + child + " " + n + " times in 20 periods");
                int full = sent(sim, parent, child, 0, MessageType.STATUS).size();
                assertEquals(0, full, parent + " sent " + child + " " + full + " whole statuses in a team where nothing changed");
            }
        }
    }

    @Test
    void unchangedSubtreeReportsGoOnceInSixteenHeartbeats() {
        TeamSimulation sim = formedTeam(53);
        sim.run(32 * PERIOD);
        for (String parent : List.of("cdr", "s1", "s2")) {
            for (String child : sim.cell(parent).children().keySet()) {
                int n = sent(sim, child, parent, 0, MessageType.SUBTREE_REPORT).size();
                int beats = sent(sim, child, parent, 0, MessageType.HEARTBEAT).size();
                // 32 heartbeats, a report with every sixteenth: two (three with the jitter); with
                // every fourth, as before, eight.
                assertTrue(beats >= 31 && n >= 1 && n <= 3, child + " sent " + n + " reports with " + beats + " heartbeats");
            }
        }
    }

    @Test
    void aChangedStatusGoesWholeUntilTheChildsHeartbeatNamesIt_evenWhenTheFirstCopiesAreLost() {
        TeamSimulation sim = formedTeam(54);
        List<String> children = new ArrayList<>(sim.cell("cdr").children().keySet());
        assertTrue(children.size() >= 2, "cdr has two children: " + children);
        String cut = children.get(0);
        String leaving = children.get(1);
        // Nothing from cdr reaches `cut` for two periods (well within its lease), while the team
        // shrinks: cdr's status changes (its team size), so its answers to `cut` are whole statuses,
        // all lost.
        sim.network().setLink(sim.address("cdr"), sim.address(cut), LinkProfile.DEFAULT.withLoss(1.0));
        long cutAt = sim.nowMillis();
        sim.leave(leaving);
        sim.run(2 * PERIOD);
        assertTrue(sent(sim, "cdr", cut, cutAt, MessageType.STATUS).size() >= 1, "cdr's status changed while the link was cut");
        sim.network().clearLinks();
        long healedAt = sim.nowMillis();
        sim.run(4 * PERIOD);
        List<Sent> after = sent(sim, "cdr", cut, healedAt, MessageType.STATUS, MessageType.ECHO);
        assertTrue(after.size() >= 3, "cdr answered " + cut + " " + after.size() + " times in 4 periods");
        // The child still names the old version: the first answer after the cut is the whole status
        // (an answer sent whole only when the status changes would be an echo here) ...
        assertEquals(MessageType.STATUS.code(), after.get(0).type(), "the first answer after the cut: " + after);
        // ... and once its heartbeat names the new version, echoes again.
        assertEquals(MessageType.ECHO.code(), after.get(after.size() - 1).type(), "the last answer: " + after);
        assertTrue(sim.cell("cdr").children().containsKey(cut), "the child kept its seat");
    }

    @Test
    void aChildWhoseHeartbeatsAreLostStillHearsItsParent() {
        TeamSimulation sim = formedTeam(52);
        String child = sim.cell("cdr").children().keySet().iterator().next();
        sim.network().setLink(sim.address(child), sim.address("cdr"), LinkProfile.DEFAULT.withLoss(1.0));
        int failuresBefore = failures();
        sim.run(5 * PERIOD); // shorter than the failure timeout (six periods)
        int n = answers(sim, "cdr", child);
        // Unanswered heartbeats: the tick sends a status when none went for a period and a half, so
        // two or three in five periods (none at all if only heartbeats were answered).
        assertTrue(n >= 2 && n <= 4, "cdr sent " + n + " statuses to " + child + " while its heartbeats were lost");
        sim.network().clearLinks();
        sim.run(4 * PERIOD);
        assertEquals(failuresBefore, failures(), "no failure declared");
        assertTrue(sim.cell("cdr").children().containsKey(child));
    }

    @Test
    void repeatedSubtreeReportsMoveNoManagersLinks() {
        TeamSimulation sim = formedTeam(55);
        Map<String, Long> before = new TreeMap<>();
        for (String parent : List.of("cdr", "s1", "s2")) {
            before.put(parent, sim.cell(parent).linkVersion());
        }
        sim.run(32 * PERIOD);
        int reports = 0;
        for (String parent : before.keySet()) {
            for (String child : sim.cell(parent).children().keySet()) {
                reports += sent(sim, child, parent, 0, MessageType.SUBTREE_REPORT).size();
            }
        }
        Map<String, Long> after = new TreeMap<>();
        for (String parent : before.keySet()) {
            after.put(parent, sim.cell(parent).linkVersion());
        }
        // Every child repeated its unchanged report (twice in 32 heartbeats); a manager that took
        // each repeat for a change would have moved its links (and rebuilt its own report) as often.
        assertTrue(reports >= 6, reports + " subtree reports in 32 periods");
        assertEquals(before, after, "the managers' link versions while nothing changed");
    }

    private int failures() {
        return (int) events.stream().filter(e -> e.kind() == CellEvent.Kind.FAILURE).count();
    }
}
