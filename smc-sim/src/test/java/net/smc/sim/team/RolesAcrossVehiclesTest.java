package net.smc.sim.team;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.math.BigDecimal;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import net.smc.core.cell.Cell;
import net.smc.core.cell.Missions;
import net.smc.core.role.TaskProvider;
import net.smc.core.task.Attr;
import net.smc.core.task.StateHandover;
import net.smc.core.task.Task;
import net.smc.core.task.TaskEvent;
import net.smc.core.task.TaskInterface;
import net.smc.policy.api.AuthMode;
import net.smc.policy.runtime.PArray;
import net.smc.policy.api.Op;
import org.junit.jupiter.api.Test;

/**
 * Roles across vehicles (section II-B.2.A) in a whole team on the virtual clock, with authorisation
 * on and a default of deny, as deployed: the shipped auth.p2 files decide.
 */
class RolesAcrossVehiclesTest {

    @TaskInterface("Explorer")
    public interface ExplorerI {
        @Op("explore")
        void explore();
    }

    @TaskInterface("Aggregator")
    public interface AggregatorI {
        @Op("report:x:y:")
        String report(String kind, double x, double y);

        @Op("hazards")
        List<Object> hazards();
    }

    @TaskInterface("HazardDetector")
    public interface HazardDetectorI {
        @Op("sniff")
        void sniff();

        @TaskEvent
        void hazardDetected(@Attr("name") String name, @Attr("uav") String uav, @Attr("kind") String kind,
                            @Attr("x") double x, @Attr("y") double y);
    }

    @TaskInterface("Relay")
    public interface RelayI {
        @Op("relay")
        void relay();
    }

    /** Hands over where it was and what it mapped. */
    public static final class Explorer extends Task implements ExplorerI, StateHandover {
        Map<String, Object> state = new LinkedHashMap<>();
        Map<String, ?> imported;

        @Override
        public void explore() {
        }

        @Override
        public Map<String, Object> exportState() {
            return new LinkedHashMap<>(state);
        }

        @Override
        public void importState(Map<String, ?> in) {
            imported = in;
        }
    }

    public static final class Aggregator extends Task implements AggregatorI {
        final List<Object> reports = new ArrayList<>();

        @Override
        public String report(String kind, double x, double y) {
            reports.add(List.of(kind, x, y));
            return "noted " + kind;
        }

        @Override
        public List<Object> hazards() {
            return List.copyOf(reports);
        }
    }

    public static final class HazardDetector extends Task implements HazardDetectorI {
        String uav;

        @Override
        public void sniff() {
        }

        @Override
        public void hazardDetected(String name, String uavId, String kind, double x, double y) {
            raise("hazardDetected", name, uavId, kind, x, y);
        }
    }

    public static final class Relay extends Task implements RelayI {
        @Override
        public void relay() {
        }
    }

    private final Map<String, Map<String, Task>> tasks = new HashMap<>();

    private TaskProvider provider(SimVehicle v) {
        Map<String, Task> own = tasks.computeIfAbsent(v.id(), id -> {
            Map<String, Task> m = new TreeMap<>();
            for (String name : v.tasks()) {
                m.put(name, switch (name) {
                    case "Explorer" -> new Explorer();
                    case "Aggregator" -> new Aggregator();
                    case "HazardDetector" -> new HazardDetector();
                    case "Relay" -> new Relay();
                    default -> throw new IllegalArgumentException("no test task " + name);
                });
            }
            return m;
        });
        return TaskProvider.of(own);
    }

    private final Map<String, SimVehicle> byId = new HashMap<>();

    private TeamSimulation formed(List<SimVehicle> team) {
        team.forEach(v -> byId.put(v.id(), v));
        TeamSimulation sim = TeamSimulation.builder(Missions.reconnaissance(), Missions.REPOSITORY, 5)
                .vehicles(team).auth(AuthMode.DENY).tasks(id -> provider(byId.get(id))).build();
        sim.start();
        settle(sim);
        return sim;
    }

    private static void settle(TeamSimulation sim) {
        try {
            assertTrue(sim.runUntil(() -> sim.invariants().settled(), 30_000),
                    () -> sim.invariants().unsettled() + "\n" + String.join("\n", sim.trace()));
        } catch (InvariantViolation v) {
            throw new AssertionError(v.report(), v);
        }
    }

    private static String holder(TeamSimulation sim, String role) {
        return sim.cells().stream().filter(c -> c.seats().stream().anyMatch(s -> s.role().equals(role)))
                .map(Cell::vehicle).findFirst().orElseThrow(() -> new AssertionError("nobody holds " + role));
    }

    private static List<Object> hazards(TeamSimulation sim) {
        Object h = sim.cell(holder(sim, "aggregator")).engine().resolve("root/role/aggregator/hazards");
        return ((PArray) h).items();
    }

    private static List<String> traced(TeamSimulation sim, String vehicle, String text) {
        return sim.trace().stream().filter(l -> l.contains(" " + vehicle + " ") && l.contains(text)).toList();
    }

    @Test
    void aDetectorsHazard_reachesTheAggregatorAndItsSurveyor_andFiresTheAggregatorsPolicy() {
        TeamSimulation sim = formed(SimVehicle.reconnaissance(1, 1, 1, 1));
        String detector = holder(sim, "hdetector");
        ((HazardDetector) tasks.get(detector).get("HazardDetector")).hazardDetected("hazardDetected", detector, "gas", 3, 4);
        sim.run(2_000);
        assertEquals(List.of(List.of("gas", new BigDecimal("3.0"), new BigDecimal("4.0"), detector)),
                hazards(sim).stream().map(o -> ((PArray) o).items()).toList(), () -> String.join("\n", sim.trace()));
        assertEquals(1, traced(sim, holder(sim, "surveyor"), "DELIVERED").size(), () -> String.join("\n", sim.trace()));
        assertEquals(1, traced(sim, holder(sim, "aggregator"), "DELIVERED").size(), () -> String.join("\n", sim.trace()));
    }

    @Test
    void anEventFromARoleTheAggregatorDoesNotAllow_isRefusedWithAnErrorAnswer_andChangesNothing() {
        TeamSimulation sim = formed(SimVehicle.reconnaissance(1, 1, 1, 1));
        String relay = holder(sim, "relay");
        sim.cell(relay).publish("relay", "hazardDetected", List.of("hazardDetected", relay, "fake", 1, 1));
        sim.run(2_000);
        assertEquals(List.of(), hazards(sim), () -> String.join("\n", sim.trace()));
        assertTrue(traced(sim, relay, "error answer from").stream().anyMatch(l -> l.contains("denied")),
                () -> String.join("\n", sim.trace()));
        assertTrue(traced(sim, holder(sim, "aggregator"), "DELIVERED").isEmpty());
    }

    @Test
    void aRemoteInvocation_returnsItsValue_andADeniedOneReturnsTheError() {
        TeamSimulation sim = formed(SimVehicle.reconnaissance(1, 1, 1, 1));
        String detector = holder(sim, "hdetector");
        String aggregator = holder(sim, "aggregator");
        long call = sim.cell(detector).invoke("hdetector", "aggregator", "report:x:y:", List.of("gas", 3, 4));
        sim.run(2_000);
        assertTrue(traced(sim, detector, "call " + call + " (aggregator report:x:y:) answered by " + aggregator
                + ": noted gas").size() == 1, () -> String.join("\n", sim.trace()));
        assertEquals(1, ((Aggregator) tasks.get(aggregator).get("Aggregator")).reports.size());

        String relay = holder(sim, "relay");
        long denied = sim.cell(relay).invoke("relay", "aggregator", "report:x:y:", List.of("fake", 1, 1));
        sim.run(2_000);
        assertTrue(traced(sim, relay, "call " + denied + " (aggregator report:x:y:) answered by " + aggregator
                + ": error").stream().anyMatch(l -> l.contains("denied")), () -> String.join("\n", sim.trace()));
        assertEquals(1, ((Aggregator) tasks.get(aggregator).get("Aggregator")).reports.size(), "nothing executed");
    }

    @Test
    void policiesUseRootTeam_toInvokeARemoteRole_andTheAnswerArrivesAsRemoteResult() {
        TeamSimulation sim = formed(SimVehicle.reconnaissance(1, 1, 1, 1));
        String detector = holder(sim, "hdetector");
        Cell cell = sim.cell(detector);
        var run = cell.engine().run("test", """
                p := root/factory/ecapolicy create.
                p event: root/event/remoteResult; action: [:call :ok :value | root print: "answer " + call + " " + ok].
                root/role/hdetector/policy at: "probe" put: p.
                p active: true.
                root/team invoke: "report:x:y:" of: "aggregator" args: #("gas" 1 2).
                """);
        assertEquals(List.of(), run.diagnostics());
        sim.run(2_000);
        assertTrue(traced(sim, detector, "answered by " + holder(sim, "aggregator") + ": noted gas").size() == 1,
                () -> String.join("\n", sim.trace()));
    }

    @Test
    void reassignment_handsTheFailedHoldersLastReportedTaskState_toTheReplacementsTask() {
        TeamSimulation sim = formed(SimVehicle.reconnaissance(2, 1, 2, 2));
        String surveyor = "s1";
        Explorer explorer = (Explorer) tasks.get(surveyor).get("Explorer");
        explorer.state.put("x", 12.5);
        explorer.state.put("mapped", List.of(List.of(1, 2), List.of(3, 4)));
        explorer.state.put("visits", Map.of("room", 2));
        sim.run(3_000);
        SimVehicle spare = SimVehicle.surveyor("s9");
        byId.put(spare.id(), spare);
        sim.join(spare);
        sim.run(3_000);
        sim.crash(surveyor);
        assertTrue(sim.runUntil(() -> sim.isLive("s9") && sim.cell("s9").seats().stream()
                .anyMatch(s -> s.role().equals("surveyor")), 30_000), () -> String.join("\n", sim.trace()));
        Explorer replacement = (Explorer) tasks.get("s9").get("Explorer");
        assertEquals(Map.of("x", new BigDecimal("12.5"),
                        "mapped", List.of(List.of(BigDecimal.ONE, new BigDecimal("2")), List.of(new BigDecimal("3"), new BigDecimal("4"))),
                        "visits", Map.of("room", new BigDecimal("2"))),
                replacement.imported, () -> String.join("\n", sim.trace()));
    }
}
