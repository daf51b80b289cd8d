package net.smc.sim.team;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HashMap;
import java.util.Map;
import java.util.TreeMap;
import net.smc.core.cell.Cell;
import net.smc.core.cell.Missions;
import net.smc.core.role.TaskProvider;
import net.smc.core.task.Task;
import net.smc.core.task.TaskInterface;
import net.smc.policy.api.DomainHandle;
import net.smc.policy.api.Op;
import org.junit.jupiter.api.Test;

/** A role's tasks come from its mission's {@code <requires><task>}: assignment starts them, withdrawal stops them. */
class RoleTasksTest {

    @TaskInterface("Explorer")
    public interface ExplorerI {
        @Op("explore")
        void explore();
    }

    @TaskInterface("Aggregator")
    public interface AggregatorI {
        @Op("collect")
        void collect();

        @Op("report:x:y:")
        void report(String kind, double x, double y);

        @Op("hazards")
        java.util.List<Object> hazards();
    }

    @TaskInterface("HazardDetector")
    public interface HazardDetectorI {
        @Op("sniff")
        void sniff();
    }

    @TaskInterface("Relay")
    public interface RelayI {
        @Op("relay")
        void relay();
    }

    /** Counts its starts and stops. */
    public abstract static class Counted extends Task {
        int starts;
        int stops;

        @Override
        protected void onStart() {
            starts++;
        }

        @Override
        protected void onStop() {
            stops++;
        }
    }

    public static final class Explorer extends Counted implements ExplorerI {
        @Override
        public void explore() {
        }
    }

    public static final class Aggregator extends Counted implements AggregatorI {
        @Override
        public void collect() {
        }

        @Override
        public void report(String kind, double x, double y) {
        }

        @Override
        public java.util.List<Object> hazards() {
            return java.util.List.of();
        }
    }

    public static final class HazardDetector extends Counted implements HazardDetectorI {
        @Override
        public void sniff() {
        }
    }

    public static final class Relay extends Counted implements RelayI {
        @Override
        public void relay() {
        }
    }

    /** Each vehicle's tasks, one instance per name, made for the task names its SimVehicle advertises. */
    private final Map<String, Map<String, Counted>> tasks = new HashMap<>();

    private TaskProvider provider(SimVehicle v) {
        Map<String, Counted> own = new TreeMap<>();
        for (String name : v.tasks()) {
            own.put(name, switch (name) {
                case "Explorer" -> new Explorer();
                case "Aggregator" -> new Aggregator();
                case "HazardDetector" -> new HazardDetector();
                case "Relay" -> new Relay();
                default -> throw new IllegalArgumentException("no test task " + name);
            });
        }
        tasks.put(v.id(), own);
        return TaskProvider.of(own);
    }

    private TeamSimulation formed() {
        var team = SimVehicle.reconnaissance(1, 1, 1, 1);
        Map<String, SimVehicle> byId = new HashMap<>();
        team.forEach(v -> byId.put(v.id(), v));
        TeamSimulation sim = TeamSimulation.builder(Missions.reconnaissance(), Missions.REPOSITORY, 3)
                .vehicles(team).tasks(id -> provider(byId.get(id))).build();
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

    private static Object atRootTask(Cell cell, String name) {
        return cell.engine().root().get("task") instanceof DomainHandle d ? d.get(name) : null;
    }

    @Test
    void assignment_startsTheTasksTheRolesMissionRequires_boundAtRootTask() {
        TeamSimulation sim = formed();
        Counted explorer = tasks.get("s1").get("Explorer");
        assertEquals("surveyor", sim.cell("s1").seats().get(0).role());
        assertTrue(explorer.isRunning());
        assertEquals(1, explorer.starts);
        assertSame(explorer.managed(), atRootTask(sim.cell("s1"), "Explorer"));
        assertFalse(tasks.get("s1").get("Relay").isRunning(), "the surveyor role does not require the Relay task");
        assertTrue(tasks.get("a1").get("Aggregator").isRunning());
    }

    @Test
    void withdrawal_stopsTheTasks_andReassignmentStartsThemAgain() {
        TeamSimulation sim = formed();
        Counted explorer = tasks.get("s1").get("Explorer");
        sim.leave("s1");
        sim.run(2_000);
        assertFalse(explorer.isRunning());
        assertEquals(1, explorer.stops);
        assertNull(atRootTask(sim.cell("s1"), "Explorer"));
        sim.rejoin("s1");
        settle(sim);
        assertTrue(sim.cell("s1").seats().stream().anyMatch(s -> s.role().equals("surveyor")), sim.cell("s1").seats()::toString);
        assertTrue(explorer.isRunning());
        assertEquals(2, explorer.starts);
    }
}
