package net.smc.sim.task;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import net.smc.core.capability.EventDescription;
import net.smc.core.capability.EventDescription.Attribute;
import net.smc.core.capability.OperationDescription;
import net.smc.core.capability.TaskDescription;
import net.smc.core.task.Task;
import net.smc.sim.map.OccupancyGrid;
import net.smc.policy.PolicyEngine;
import net.smc.policy.api.Diagnostic;
import net.smc.policy.api.PolicyRepository;
import org.junit.jupiter.api.Test;

/** The capability descriptions of the tasks, in the shape of the paper's Table V. */
class TaskCatalogTest {
    private final TaskCatalog catalog = TaskCatalog.standard();

    @Test
    void standard_namesTheSevenTasks() {
        assertEquals(new TreeSet<>(Set.of("Aggregator", "Assist", "Beacon", "Explorer", "HazardDetector", "Navigator",
                "Relay")), catalog.names());
    }

    @Test
    void navigator_operationsWithArgumentTypes_eventsWithAttributes() {
        TaskDescription d = catalog.describe("Navigator");
        assertEquals("Navigator", d.task());
        assertEquals(List.of(
                new OperationDescription("avoid", List.of("double", "double", "double")),
                new OperationDescription("clearZones", List.of()),
                new OperationDescription("goTo", List.of("double", "double")),
                new OperationDescription("halt", List.of()),
                new OperationDescription("isMoving", List.of()),
                new OperationDescription("margin", List.of("double")),
                new OperationDescription("pushAside", List.of("double", "double"))), d.operations());
        assertEquals(List.of(
                new EventDescription("arrived", List.of(new Attribute("x", "double"), new Attribute("y", "double"))),
                new EventDescription("blocked", List.of(new Attribute("x", "double"), new Attribute("y", "double")))),
                d.events());
    }

    @Test
    void explorer_eventsOfTableV() {
        TaskDescription d = catalog.describe("Explorer");
        assertEquals(List.of("areaExplored", "mapUpdate", "obstacle", "targetSighted"),
                d.events().stream().map(EventDescription::name).toList());
        assertEquals(List.of(new Attribute("tag", "String"), new Attribute("kind", "String"),
                new Attribute("x", "double"), new Attribute("y", "double")), d.events().get(3).attributes());
        assertEquals(List.of(new Attribute("name", "String"), new Attribute("uav", "String"), new Attribute("cells", "List")),
                d.events().get(1).attributes());
        assertEquals(List.of("avoid", "explore", "exploredFraction", "halt", "isExploring", "merge", "pushAside", "shareMap"),
                d.operations().stream().map(OperationDescription::name).toList());
    }

    @Test
    void theOtherTasks_carryTheirEvents() {
        assertEquals(List.of(new EventDescription("hazardDetected", List.of(new Attribute("name", "String"),
                new Attribute("uav", "String"), new Attribute("kind", "String"),
                new Attribute("x", "double"), new Attribute("y", "double"))), new EventDescription("inspected",
                List.of(new Attribute("x", "double"), new Attribute("y", "double"), new Attribute("found", "boolean")))),
                catalog.describe("HazardDetector").events());
        assertTrue(catalog.describe("HazardDetector").operations()
                .contains(new OperationDescription("inspect", List.of("double", "double"))));
        assertTrue(catalog.describe("HazardDetector").operations()
                .contains(new OperationDescription("pushAside", List.of("double", "double"))));
        assertEquals(List.of("hazardAdded"), eventNames("Aggregator"));
        assertTrue(catalog.describe("Aggregator").operations()
                .contains(new OperationDescription("report", List.of("String", "double", "double"))));
        assertEquals(List.of(new EventDescription("linkQuality", List.of(new Attribute("name", "String"),
                new Attribute("uav", "String"), new Attribute("quality", "double")))), catalog.describe("Relay").events());
        assertEquals(List.of(new EventDescription("distress", List.of(new Attribute("x", "double"),
                new Attribute("y", "double"), new Attribute("condition", "String")))), catalog.describe("Beacon").events());
        assertEquals(List.of("assisted"), eventNames("Assist"));
    }

    @Test
    void describe_anUnknownTask_listsTheKnownOnes() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> catalog.describe("Teleporter"));
        assertEquals("unknown task 'Teleporter'; the known tasks are Aggregator, Assist, Beacon, Explorer, HazardDetector,"
                + " Navigator, Relay", e.getMessage());
    }

    @Test
    void create_makesEachTaskForTheRobot_andEachBindsToACell() throws Exception {
        FakeWorld world = new FakeWorld(5, 5);
        TaskContext context = new TaskContext(world.robot("r1", 1, 1, 0), new OccupancyGrid(0, 0, 5, 5, 0.25));
        EventLog log = new EventLog();
        for (String name : catalog.names()) {
            Task task = catalog.create(name, context);
            assertEquals(catalog.type(name), task.getClass());
            assertEquals(catalog.describe(name), task.describe());
            log.watch(task);
            assertTrue(log.cell.root().get("task") instanceof net.smc.policy.api.DomainHandle d && d.get(name) != null,
                    name + " at root/task");
        }
        log.assertNoErrors();
    }

    @Test
    void everyTask_bindsInACellBootedWithTheArchitecturesEvents() throws Exception {
        // A vehicle's cell boots with policy:/boot/events before any role loads; a task whose event
        // shares a template's name must carry that template's attributes, or its role cannot load.
        List<Diagnostic> errors = new ArrayList<>();
        PolicyEngine cell = PolicyEngine.builder().errors(errors::add)
                .repository(new PolicyRepository(Path.of(System.getProperty("smc.repo.dir")))).build();
        assertTrue(cell.load("policy:/boot/events").ok(), "boot: " + errors);
        TaskContext context = new TaskContext(new FakeWorld(5, 5).robot("r1", 1, 1, 0), new OccupancyGrid(0, 0, 5, 5, 0.25));
        for (String name : catalog.names()) {
            catalog.create(name, context).bind(cell);
        }
        assertEquals(List.of(), errors);
    }

    @Test
    void builder_refusesTwoTasksOfOneName() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> TaskCatalog.builder()
                .add(Relay.class, Relay::new).add(Relay.class, Relay::new));
        assertTrue(e.getMessage().contains("already has a task named 'Relay'"), e.getMessage());
    }

    private List<String> eventNames(String task) {
        return catalog.describe(task).events().stream().map(EventDescription::name).toList();
    }
}
