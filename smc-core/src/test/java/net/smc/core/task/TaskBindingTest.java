package net.smc.core.task;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import net.smc.policy.PolicyEngine;
import net.smc.policy.api.Diagnostic;
import net.smc.policy.RunResult;
import net.smc.policy.api.DomainHandle;
import net.smc.policy.api.EventHandle;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * Tasks as managed objects of a cell: policies invoke their operations at {@code root/task/<name>}
 * and react to their events at {@code root/event/<event>}.
 */
class TaskBindingTest {
    @TaskInterface("Bumper")
    interface BumperI {
        @TaskEvent
        void obstacle(@Attr("x") double x, @Attr("y") double y);
    }

    /** Another task raising the Explorer's {@code obstacle} event. */
    static class Bumper extends Task implements BumperI {
        @Override
        public void obstacle(double x, double y) {
            raise("obstacle", x, y);
        }
    }

    private final List<String> output = new ArrayList<>();
    private final List<Diagnostic> errors = new ArrayList<>();
    private PolicyEngine cell;
    private Explorer explorer;

    @BeforeEach
    void newCell() {
        cell = PolicyEngine.builder().output(output::add).errors(errors::add).build();
        explorer = new Explorer();
    }

    private void run(String text) {
        RunResult result = cell.run("test.p2", text);
        assertEquals(List.of(), errors, "errors of " + text);
        assertTrue(result.ok(), text);
    }

    @Test
    void obligationPolicy_reactsToTheTasksEventByInvokingItsOperation() throws Exception {
        explorer.bind(cell);
        run("""
                p := root/factory/ecapolicy create.
                p event: /event/obstacle;
                  condition: [:x | x > 0];
                  action: [:x :y | root print: "obstacle at " + x + "," + y.
                                   root/task/Explorer moveTo: x + 1 y: y - 1].
                p active: true.
                """);
        explorer.sense(3, 4);
        assertEquals(4.0, explorer.x);
        assertEquals(3.0, explorer.y);
        assertEquals(List.of("obstacle at 3.0,4.0"), output);
        assertEquals(List.of(), errors);
    }

    @Test
    void anOperationInvokedByAPolicy_canRaiseAnEventThatTriggersAnotherPolicy() throws Exception {
        explorer.bind(cell);
        run("""
                p := root/factory/ecapolicy create.
                p event: /event/obstacle; action: [:x | root/task/Explorer explore: "near" + x].
                p active: true.
                q := root/factory/ecapolicy create.
                q event: /event/arrived; action: [:area | root print: "arrived " + area].
                q active: true.
                """);
        explorer.sense(1, 2);
        assertEquals("near1.0", explorer.area);
        assertEquals(List.of("arrived near1.0"), output);
        assertEquals(List.of(), errors);
    }

    @Test
    void obligationPolicy_conditionFalse_leavesTheTaskAlone() throws Exception {
        explorer.bind(cell);
        run("""
                p := root/factory/ecapolicy create.
                p event: /event/obstacle; condition: [:x | x > 0]; action: [:x :y | root/task/Explorer moveTo: 9 y: 9].
                p active: true.
                """);
        explorer.sense(-1, 4);
        assertEquals(0.0, explorer.x);
    }

    @Test
    void bind_makesOneTemplatePerEventNamedByItsAttributes() throws Exception {
        explorer.bind(cell);
        assertEquals(List.of("x", "y"), cell.template("root/event/obstacle").attributeNames());
        assertEquals(List.of("area"), cell.template("root/event/arrived").attributeNames());
    }

    @Test
    void bind_putsTheTaskAtRootTaskName() throws Exception {
        explorer.bind(cell);
        assertSame(explorer.managed(), cell.resolve("root/task/Explorer"));
        run("root/task/Explorer explore: \"cellar\"");
        assertEquals("cellar", explorer.area);
        assertEquals("0.0,0.0", PolicyEngine.print(cell.run("t", "root/task/Explorer position").value()));
    }

    @Test
    void policies_canStartAndStopTheTask() throws Exception {
        explorer.bind(cell);
        run("root/task/Explorer start");
        assertTrue(explorer.isRunning());
        assertEquals("true", PolicyEngine.print(cell.run("t", "root/task/Explorer isRunning").value()));
        run("root/task/Explorer stop");
        assertFalse(explorer.isRunning());
        assertEquals("Explorer", PolicyEngine.print(cell.run("t", "root/task/Explorer name").value()));
    }

    @Test
    void bind_reusesATemplateAPolicyMadeWithTheSameAttributes() throws Exception {
        run("""
                root/event at: "obstacle" put: (root/factory/event create: #("x" "y")).
                p := root/factory/ecapolicy create.
                p event: root/event/obstacle; action: [:x | root print: x].
                p active: true.
                """);
        EventHandle before = cell.template("root/event/obstacle");
        explorer.bind(cell);
        assertSame(before, cell.template("root/event/obstacle"));
        explorer.sense(7, 8);
        assertEquals(List.of("7.0"), output);
    }

    @Test
    void twoTasksRaisingTheSameEvent_shareItsTemplate() throws Exception {
        explorer.bind(cell);
        EventHandle first = cell.template("root/event/obstacle");
        Bumper bumper = new Bumper();
        bumper.bind(cell);
        assertSame(first, cell.template("root/event/obstacle"));
        run("""
                p := root/factory/ecapolicy create.
                p event: /event/obstacle; action: [:x :y | root print: x].
                p active: true.
                """);
        bumper.obstacle(1, 2);
        explorer.obstacle(3, 4);
        assertEquals(List.of("1.0", "3.0"), output);
    }

    @Test
    void bind_toASecondCell_failsUntilUnbound() throws Exception {
        explorer.bind(cell);
        PolicyEngine other = PolicyEngine.builder().build();
        IllegalStateException e = assertThrows(IllegalStateException.class, () -> explorer.bind(other));
        assertEquals("task Explorer is already bound to another cell; unbind it first", e.getMessage());
        explorer.unbind();
        explorer.bind(other);
        assertSame(explorer.managed(), other.resolve("root/task/Explorer"));
    }

    @Test
    void bind_failsOnATemplateWithOtherAttributes_andChangesNothing() {
        run("root/event at: \"obstacle\" put: (root/factory/event create: #(\"where\")).");
        IllegalStateException e = assertThrows(IllegalStateException.class, () -> explorer.bind(cell));
        assertEquals("cannot bind task Explorer: root/event/obstacle is an event template with attributes [where],"
                + " but the task's event 'obstacle' has [x, y]; an event's attribute names must match its template's",
                e.getMessage());
        assertFalse(explorer.isBound());
        assertNull(((DomainHandle) cell.resolve("root/event")).get("arrived"), "no template made");
        assertNull(cell.root().get("task"), "no task domain made");
    }

    @Test
    void bind_failsWhenTheEventPathHoldsSomethingElse() {
        run("root/event at: \"arrived\" put: 5.");
        IllegalStateException e = assertThrows(IllegalStateException.class, () -> explorer.bind(cell));
        assertTrue(e.getMessage().startsWith("root/event/arrived holds 5, not an event template"), e.getMessage());
    }

    @Test
    void bind_failsWhenAnotherTaskOfTheSameNameIsThere() throws Exception {
        explorer.bind(cell);
        IllegalStateException e = assertThrows(IllegalStateException.class, () -> new Explorer().bind(cell));
        assertTrue(e.getMessage().startsWith("root/task/Explorer holds <Explorer root/task/Explorer>, not this task"),
                e.getMessage());
    }

    @Test
    void bind_ofATaskThatCannotBeDescribed_failsWithTheDescriptionError() {
        TaskDescriptionException e = assertThrows(TaskDescriptionException.class, () -> new Mapper().bind(cell));
        assertTrue(e.getMessage().contains("whose @TaskInterface names 'Surveyor'"), e.getMessage());
        assertNull(cell.root().get("task"));
    }

    @Test
    void bind_refusesATaskWhoseNameCannotBeAPath() {
        Task anonymous = new Task() { };
        IllegalStateException e = assertThrows(IllegalStateException.class, () -> anonymous.bind(cell));
        assertTrue(e.getMessage().contains("has the name '', which is not a PonderTalk identifier"), e.getMessage());
        assertNull(cell.root().get("task"));
    }

    @Test
    void bind_twiceToTheSameCell_doesNothing() throws Exception {
        explorer.bind(cell);
        explorer.bind(cell);
        assertTrue(explorer.isBound());
    }

    @Test
    void unbind_removesTheTaskButKeepsTheTemplates() throws Exception {
        explorer.bind(cell);
        explorer.unbind();
        assertFalse(explorer.isBound());
        assertNull(((DomainHandle) cell.root().get("task")).get("Explorer"));
        assertEquals(List.of("x", "y"), cell.template("root/event/obstacle").attributeNames());
    }

    @Test
    void raise_whileUnbound_isCountedAndGoesNowhere() {
        explorer.sense(1, 2);
        explorer.arrived("yard");
        assertEquals(2, explorer.droppedEvents());
    }

    @Test
    void raise_ofAnUndeclaredEvent_isAnErrorNamingTheEvents() throws Exception {
        explorer.bind(cell);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, explorer::raiseUndeclared);
        assertEquals("task Explorer has no event 'meteor'; its events are [arrived, obstacle]", e.getMessage());
    }

    @Test
    void raise_withTheWrongNumberOfValues_isAnError() throws Exception {
        explorer.bind(cell);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, explorer::raiseTooFew);
        assertEquals("task Explorer raised 'obstacle' with 1 values; the event has 2 attributes [x, y]", e.getMessage());
    }

    @Test
    void raise_answersWhetherTheEventWasDelivered() throws Exception {
        explorer.bind(cell);
        assertTrue(explorer.raise("arrived", "yard"));
        assertFalse(explorer.raise("obstacle", Double.NaN, 1.0), "NaN is no PonderTalk number; the cell reports it");
        assertEquals(1, errors.size());
    }

    @Test
    void managed_isTheSameHandleEveryTime() {
        assertSame(explorer.managed(), explorer.managed());
    }
}
