package net.smc.sim.team;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Optional;

import net.smc.core.cell.MissionState;
import net.smc.core.cell.Missions;
import org.junit.jupiter.api.Test;

/**
 * A free vehicle the commander's policies pass over keeps answering discovery (every heartbeat
 * period while a seat is open): the policies are asked about it once, and again only when they,
 * or what the vehicle presents, change, or after the bound on remembering a refusal (four failure
 * timeouts, 12 s in the reconnaissance mission).
 */
class RefusedVehicleTest {
    /** A policy of the commander that notes every newUAV and asks for nothing. */
    private static final String WATCH = """
            w := root/factory/ecapolicy create.
            w event: /event/newUAV; action: [:uav | root print: "seen " + uav].
            w active: true.
            root/role/commander/policy/assignSurveyor active: false.
            """;

    private final List<String> seen = Collections.synchronizedList(new ArrayList<>());

    private TeamSimulation team(long seed) {
        TeamSimulation sim = TeamSimulation.builder(Missions.reconnaissance(), Missions.REPOSITORY, seed)
                .vehicles(SimVehicle.reconnaissance(2, 1, 0, 0))
                .output((vehicle, line) -> {
                    if (vehicle.equals("cdr") && line.startsWith("seen ")) {
                        seen.add(line.substring(5));
                    }
                }).build();
        sim.start();
        sim.cell("cdr").engine().run("watch.p2", WATCH);
        return sim;
    }

    private long seenOf(String vehicle) {
        synchronized (seen) {
            return seen.stream().filter(vehicle::equals).count();
        }
    }

    private static boolean holdsSurveyor(TeamSimulation sim, String vehicle) {
        return sim.cell(vehicle).seats().stream().anyMatch(s -> s.role().equals("surveyor"));
    }

    /**
     * A refusal holds for the open seats it was made for: a surveyor decided on while the
     * aggregator's seat was still open is put to the policies once more when that seat is taken
     * (seats are given as the discovery replies come, so which replies come before the aggregator's
     * depends on the run), and then not again in twenty heartbeat periods.
     */
    @Test
    void aRefusedVehicleAnsweringDiscoveryForTwentyRoundsIsPutToThePoliciesOnce() {
        TeamSimulation sim = team(41);
        assertTrue(sim.runUntil(() -> sim.cell("a1").seats().stream().anyMatch(s -> s.role().equals("aggregator")), 2_000),
                "the aggregator is recruited");
        long s1Before = seenOf("s1");
        long s2Before = seenOf("s2");
        sim.run(10_000); // twenty heartbeat periods, the surveyor seats open all along
        assertTrue(seenOf("s1") >= 1 && seenOf("s1") - s1Before <= 1, "newUAV for s1, refused, in 10 s: " + seen);
        assertTrue(seenOf("s2") >= 1 && seenOf("s2") - s2Before <= 1, "newUAV for s2, refused, in 10 s: " + seen);
        assertTrue(seenOf("s1") <= 2 && seenOf("s2") <= 2, "newUAV in 10 s: " + seen);
        assertTrue(!holdsSurveyor(sim, "s1") && !holdsSurveyor(sim, "s2"));
    }

    @Test
    void aRefusalIsForgottenAfterItsBound() {
        TeamSimulation sim = team(42);
        sim.run(26_000);
        // Asked at about 0, 12 and 24 s: each refusal remembered 12 s, not for ever, not every period.
        assertEquals(3, seenOf("s1"), "newUAV for s1 in 26 s: " + seen);
    }

    @Test
    void enablingTableIAgainReconsidersTheRefusedVehicles() {
        TeamSimulation sim = team(43);
        sim.run(5_000);
        assertEquals(1, seenOf("s1"));
        sim.cell("cdr").engine().run("enable.p2", "root/role/commander/policy/assignSurveyor active: true.");
        assertTrue(sim.runUntil(() -> sim.cell("cdr").missionState().equals(Optional.of(MissionState.RUNNING)), 3_000),
                "the surveyors are recruited once Table I is enabled again");
        assertTrue(holdsSurveyor(sim, "s1") && holdsSurveyor(sim, "s2"));
        assertEquals(2, seenOf("s1"), "put to the policies once more after the change: " + seen);
    }

    @Test
    void loadingANewRuleReconsidersTheRefusedVehicles() {
        TeamSimulation sim = team(44);
        sim.run(5_000);
        assertEquals(1, seenOf("s2"));
        sim.cell("cdr").engine().run("rule.p2", """
                q := root/factory/ecapolicy create.
                q event: /event/newUAV; action: [:uav | root/discovery fullCapReq: uav role: "surveyor"].
                q active: true.
                """);
        assertTrue(sim.runUntil(() -> holdsSurveyor(sim, "s1") && holdsSurveyor(sim, "s2"), 3_000),
                "the surveyors are recruited by the new rule");
    }
}
