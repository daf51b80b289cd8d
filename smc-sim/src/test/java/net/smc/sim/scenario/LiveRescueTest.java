package net.smc.sim.scenario;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;

import net.smc.core.transport.udp.UdpCounters;
import net.smc.sim.render.Timeline;
import net.smc.sim.team.LiveTeam;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The rescue with every cell on its own UDP sockets over loopback, signed traffic, and the world
 * stepped on the wall clock at 2 mission seconds per wall second (about 20 s of wall time a run):
 * it succeeds, the seven steps are on the timeline, the aggregator takes over, the stopped robot
 * is cut off by its broken radio (the world's radio filters what arrives over the sockets), and the
 * datagrams went through the sockets. The mission-time limit is generous: on a loaded machine a live run
 * is slower than a simulated one, never faster.
 */
class LiveRescueTest {
    private static final Path PROJECT = Path.of(System.getProperty("smc.project.dir", ".."));
    private static final double SPEED = 2;

    @ParameterizedTest
    @ValueSource(longs = {1, 2})
    void rescueOverLoopbackUdp_succeeds(long seed) throws Exception {
        try (RescueScenario s = RescueScenario.loadLive(PROJECT, RescueScenario.Settings.of(seed).withLimit(150_000),
                SPEED, row -> { })) {
            RescueScenario.Outcome o = s.run();
            String trace = "seed " + seed + ": " + o.reason() + "\n"
                    + String.join("\n", s.timeline().rows().stream().map(RescueScenario::format).toList());
            LiveTeam team = (LiveTeam) s.team();
            UdpCounters udp = team.udpCounters();
            var errors = s.diagnostics();
            s.close();

            assertTrue(o.succeeded(), trace);
            assertEquals("r1".equals(o.firstSurveyor()) ? "r2" : "r1", o.secondSurveyor(), trace);
            assertTrue(o.firstStopMillis() >= 0 && o.reassignedMillis() > o.firstStopMillis(), trace);
            Set<String> steps = new TreeSet<>();
            for (Timeline.Row r : s.timeline().rows()) {
                steps.add(r.step());
            }
            assertTrue(steps.containsAll(List.of("i", "ii", "iii", "iv", "v", "vi", "vii")), "steps " + steps + "\n" + trace);
            boolean cutOff = s.timeline().rows().stream().anyMatch(r -> r.vehicle().equals(o.firstSurveyor())
                    && r.timeMillis() > o.firstStopMillis() && (r.what().equals("SUSPENDED") || r.what().equals("TOOK_OVER")));
            assertTrue(cutOff, "the stopped robot's broken radio cuts it off from the team on UDP too\n" + trace);
            assertTrue(udp.sent() + udp.broadcastsSent() > 50 && udp.delivered() > 50,
                    () -> "datagrams through the UDP sockets: " + udp);
            assertTrue(errors.isEmpty(), () -> "policy errors: " + errors);
        }
    }
}
