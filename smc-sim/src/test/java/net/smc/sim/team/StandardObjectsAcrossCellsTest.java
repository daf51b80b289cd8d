package net.smc.sim.team;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.math.BigDecimal;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import net.smc.core.cell.Cell;
import net.smc.core.cell.Missions;
import net.smc.core.role.TaskProvider;
import net.smc.core.task.Task;
import net.smc.policy.RunResult;
import net.smc.policy.api.AuthMode;
import org.junit.jupiter.api.Test;

/**
 * The standard objects' forms that reach another cell (EventForwarder {@code forwardTo:
 * "/team/<cell>/<path>"}, PonderTalk {@code create: "/team/<cell>"}) in a team on the virtual
 * clock, authorisation on with a default of deny: the receiving cell's policies decide, and a
 * refusal comes back to the sender as an error.
 */
class StandardObjectsAcrossCellsTest {
    private final Map<String, SimVehicle> byId = new HashMap<>();

    private TeamSimulation formed() {
        List<SimVehicle> team = SimVehicle.reconnaissance(1, 1, 1, 1);
        team.forEach(v -> byId.put(v.id(), v));
        TeamSimulation sim = TeamSimulation.builder(Missions.reconnaissance(), Missions.REPOSITORY, 11)
                .vehicles(team).auth(AuthMode.DENY).tasks(id -> provider(byId.get(id))).build();
        sim.start();
        assertTrue(sim.runUntil(() -> sim.invariants().settled(), 30_000), () -> String.join("\n", sim.trace()));
        return sim;
    }

    private static TaskProvider provider(SimVehicle v) {
        Map<String, Task> own = new TreeMap<>();
        for (String name : v.tasks()) {
            own.put(name, switch (name) {
                case "Explorer" -> new RolesAcrossVehiclesTest.Explorer();
                case "Aggregator" -> new RolesAcrossVehiclesTest.Aggregator();
                case "HazardDetector" -> new RolesAcrossVehiclesTest.HazardDetector();
                case "Relay" -> new RolesAcrossVehiclesTest.Relay();
                default -> throw new IllegalArgumentException("no test task " + name);
            });
        }
        return TaskProvider.of(own);
    }

    private static String holder(TeamSimulation sim, String role) {
        return sim.cells().stream().filter(c -> c.seats().stream().anyMatch(s -> s.role().equals(role)))
                .map(Cell::vehicle).findFirst().orElseThrow(() -> new AssertionError("nobody holds " + role));
    }

    private static void run(Cell cell, String text) {
        RunResult r = cell.engine().run("test", text);
        assertEquals(List.of(), r.diagnostics(), text);
    }

    /** The aggregator's cell: a ping template, a policy storing its level in root, and the given permission. */
    private static void receiver(Cell aggregator, String allowedAction) {
        run(aggregator, """
                root/event at: "ping" put: (root/factory/event create: #("level")).
                p := root/factory/ecapolicy create.
                p event: root/event/ping; action: [:level | root at: "pinged" put: level].
                p active: true.
                """);
        if (allowedAction != null) {
            run(aggregator, "(root/factory/authpolicy subject: root/role/aggregator/peers/hdetector action: \""
                    + allowedAction + "\" target: root/role/aggregator focus: \"st\") active: true.");
        }
    }

    /** A cell that forwards its pings to the aggregator's role domain and keeps the last remoteResult in root. */
    private static void sender(Cell cell, String aggregator) {
        run(cell, """
                root/event at: "ping" put: (root/factory/event create: #("level")).
                r := root/factory/ecapolicy create.
                r event: root/event/remoteResult;
                  action: [:ok :value :error | root at: "ok" put: ok. root at: "value" put: value. root at: "error" put: error].
                r active: true.
                f := (root load: "EventForwarder") create.
                f attachTo: root; forward: root/event/ping; forwardTo: "/team/%s/role/aggregator".
                f active: true.
                """.formatted(aggregator));
    }

    private static Object at(Cell cell, String name) {
        return cell.engine().root().get(name);
    }

    @Test
    void anEventForwardedToAnotherCell_firesItsPolicy_whenItsAuthorisationsAllowIt() {
        TeamSimulation sim = formed();
        Cell aggregator = sim.cell(holder(sim, "aggregator"));
        Cell detector = sim.cell(holder(sim, "hdetector"));
        receiver(aggregator, "forwardTo:");
        sender(detector, aggregator.vehicle());

        run(detector, "root/event/ping create: #(7).");
        sim.run(2_000);

        assertEquals(new BigDecimal("7"), at(aggregator, "pinged"), () -> String.join("\n", sim.trace()));
        assertEquals(Boolean.TRUE, at(detector, "ok"), () -> String.join("\n", sim.trace()));
    }

    @Test
    void anEventForwardedToAnotherCell_isRefused_andTheSenderGetsTheError_whenNoAuthorisationAllowsIt() {
        TeamSimulation sim = formed();
        Cell aggregator = sim.cell(holder(sim, "aggregator"));
        Cell detector = sim.cell(holder(sim, "hdetector"));
        receiver(aggregator, null);
        sender(detector, aggregator.vehicle());

        run(detector, "root/event/ping create: #(7).");
        sim.run(2_000);

        assertEquals(null, at(aggregator, "pinged"), "the policy did not fire");
        assertEquals(Boolean.FALSE, at(detector, "ok"), () -> String.join("\n", sim.trace()));
        assertTrue(String.valueOf(at(detector, "error")).contains("denied by the authorisation policies of role 'aggregator'"),
                () -> String.valueOf(at(detector, "error")));
        assertTrue(sim.trace().stream().anyMatch(l -> l.contains(" " + detector.vehicle() + " ")
                && l.contains("policy error: EventForwarder: event 'ping' forwarded to /team/" + aggregator.vehicle())
                && l.contains("denied")), () -> String.join("\n", sim.trace()));
    }

    private static void remotePonderTalk(Cell cell, String to, String text) {
        run(cell, """
                r := root/factory/ecapolicy create.
                r event: root/event/remoteResult;
                  action: [:ok :value :error | root at: "ok" put: ok. root at: "value" put: value. root at: "error" put: error].
                r active: true.
                pt := (root load: "PonderTalk") create: "/team/%s".
                root at: "call" put: (pt execute: "%s").
                """.formatted(to, text));
    }

    @Test
    void remoteExecute_evaluatesTheTextThere_andTheValueComesBackAsRemoteResult_whenAllowed() {
        TeamSimulation sim = formed();
        Cell aggregator = sim.cell(holder(sim, "aggregator"));
        Cell detector = sim.cell(holder(sim, "hdetector"));
        receiver(aggregator, "evaluate:");

        remotePonderTalk(detector, aggregator.vehicle(), "x := 6. x * 7.");
        sim.run(2_000);

        assertEquals(Boolean.TRUE, at(detector, "ok"), () -> at(detector, "error") + "\n" + String.join("\n", sim.trace()));
        assertEquals(new BigDecimal("42"), at(detector, "value"));
    }

    @Test
    void remoteExecute_isDeniedByDefault_andTheSenderGetsTheError() {
        TeamSimulation sim = formed();
        Cell aggregator = sim.cell(holder(sim, "aggregator"));
        Cell detector = sim.cell(holder(sim, "hdetector"));
        receiver(aggregator, "forwardTo:");

        remotePonderTalk(detector, aggregator.vehicle(), "root/event/ping create: #(99).");
        sim.run(2_000);

        assertEquals(Boolean.FALSE, at(detector, "ok"), () -> String.join("\n", sim.trace()));
        assertTrue(String.valueOf(at(detector, "error")).contains("Ponder2AuthorizationException: evaluate:"),
                () -> String.valueOf(at(detector, "error")));
        assertEquals(null, at(aggregator, "pinged"), "nothing of the text ran");
    }

    @Test
    void remoteExecute_runsItsSendsUnderTheReceiversAuthorisations_soAForbiddenSendIsAnErrorAnswer() {
        TeamSimulation sim = formed();
        Cell aggregator = sim.cell(holder(sim, "aggregator"));
        Cell detector = sim.cell(holder(sim, "hdetector"));
        receiver(aggregator, "evaluate:");

        remotePonderTalk(detector, aggregator.vehicle(), "root/role/aggregator/task listNames.");
        sim.run(2_000);

        assertEquals(Boolean.FALSE, at(detector, "ok"), () -> String.join("\n", sim.trace()));
        assertTrue(String.valueOf(at(detector, "error")).contains("Ponder2AuthorizationException: listNames"),
                () -> String.valueOf(at(detector, "error")));
    }
}
