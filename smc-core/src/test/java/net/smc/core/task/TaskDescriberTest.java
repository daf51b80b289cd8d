package net.smc.core.task;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeFalse;

import java.util.List;
import net.smc.core.capability.EventDescription;
import net.smc.core.capability.EventDescription.Attribute;
import net.smc.core.capability.OperationDescription;
import net.smc.core.capability.TaskDescription;
import org.junit.jupiter.api.Test;

/** The paper's Table V: the reflective capability description of one task, and its error cases. */
class TaskDescriberTest {

    // ---- fixtures beyond the shared example tasks ----

    /** A task of its own that inherits ExplorerI, which names another task. */
    static class FastExplorer extends Explorer {
    }

    interface MotionI {
        void halt();
    }

    @TaskInterface("Rover")
    interface RoverI extends MotionI {
        void drive(int speed);

        void drive(int speed, double heading);
    }

    @TaskInterface("Rover")
    interface CameraI {
        byte[] snapshot(String[] filters);

        @TaskEvent
        void seen(@Attr("what") String what);
    }

    /** Two annotated interfaces naming it, one of them with an unannotated superinterface. */
    static class Rover extends Task implements CameraI, RoverI {
        @Override
        public void halt() {
        }

        @Override
        public void drive(int speed) {
        }

        @Override
        public void drive(int speed, double heading) {
        }

        @Override
        public byte[] snapshot(String[] filters) {
            return new byte[0];
        }

        @Override
        public void seen(String what) {
        }
    }

    @TaskInterface("Drone")
    interface DroneI extends SurveyorI {
    }

    /** Names itself, but extends an annotated interface that names the Surveyor. */
    static class Drone extends Task implements DroneI {
        @Override
        public void survey(String area) {
        }
    }

    @TaskInterface("Blind")
    interface BlindI {
        @TaskEvent
        void touched(double x);
    }

    static class Blind extends Task implements BlindI {
        @Override
        public void touched(double x) {
        }
    }

    @TaskInterface("Odd")
    interface OddNameI {
        @TaskEvent
        void seen(@Attr("2x") double x);
    }

    static class Odd extends Task implements OddNameI {
        @Override
        public void seen(double x) {
        }
    }

    @TaskInterface("Twice")
    interface TwiceI {
        @TaskEvent
        void seen(@Attr("x") double x, @Attr("x") double y);
    }

    static class Twice extends Task implements TwiceI {
        @Override
        public void seen(double x, double y) {
        }
    }

    @TaskInterface("Overloaded")
    interface OverloadedI {
        @TaskEvent
        void seen(@Attr("x") double x);

        @TaskEvent
        void seen(@Attr("x") double x, @Attr("y") double y);
    }

    static class Overloaded extends Task implements OverloadedI {
        @Override
        public void seen(double x) {
        }

        @Override
        public void seen(double x, double y) {
        }
    }

    @TaskInterface("Dollar")
    interface DollarI {
        @TaskEvent
        void seen$now();
    }

    static class Dollar extends Task implements DollarI {
        @Override
        public void seen$now() {
        }
    }

    // ---- the main path ----

    @Test
    void describe_listsOperationsWithArgumentTypesAndEventsWithAttributes() throws Exception {
        TaskDescription expected = new TaskDescription("Explorer",
                List.of(new OperationDescription("explore", List.of("String")),
                        new OperationDescription("moveTo", List.of("double", "double")),
                        new OperationDescription("position", List.of())),
                List.of(new EventDescription("arrived", List.of(new Attribute("area", "String"))),
                        new EventDescription("obstacle", List.of(new Attribute("x", "double"), new Attribute("y", "double")))));
        assertEquals(expected, TaskDescriber.describe(Explorer.class));
    }

    @Test
    void describe_namesTheTaskByItsClassSimpleName() throws Exception {
        assertEquals("Explorer", TaskDescriber.describe(Explorer.class).task());
        assertEquals("Explorer", new Explorer().name());
    }

    @Test
    void describe_fromTheTaskItselfEqualsTheClassDescription() throws Exception {
        assertEquals(TaskDescriber.describe(Explorer.class), new Explorer().describe());
    }

    @Test
    void describe_ignoresUnannotatedInterfacesBesideAnAnnotatedOne() throws Exception {
        TaskDescription d = TaskDescriber.describe(Explorer.class);
        assertTrue(d.operations().stream().noneMatch(o -> o.name().equals("run")), d.toString());
    }

    @Test
    void describe_leavesOutStaticInterfaceMethods() throws Exception {
        TaskDescription d = TaskDescriber.describe(Explorer.class);
        assertTrue(d.operations().stream().noneMatch(o -> o.name().equals("unit")), d.toString());
    }

    @Test
    void describe_givesAnEmptyDescriptionWhenNoInterfaceIsAnnotated() throws Exception {
        TaskDescription d = TaskDescriber.describe(Idler.class);
        assertEquals(TaskDescription.empty("Idler"), d);
        assertTrue(d.isEmpty());
    }

    @Test
    void describe_unitesEveryInterfaceNamingTheTaskWithInheritedMethodsAndOverloadsSorted() throws Exception {
        TaskDescription d = TaskDescriber.describe(Rover.class);
        assertEquals(List.of(new OperationDescription("drive", List.of("int")),
                new OperationDescription("drive", List.of("int", "double")),
                new OperationDescription("halt", List.of()),
                new OperationDescription("snapshot", List.of("String[]"))), d.operations());
        assertEquals(List.of(new EventDescription("seen", List.of(new Attribute("what", "String")))), d.events());
    }

    // ---- Table V's error ----

    @Test
    void describe_failsWhenAnnotationNamesAnotherTask() {
        TaskDescriptionException e = assertThrows(TaskDescriptionException.class, () -> TaskDescriber.describe(Mapper.class));
        assertTrue(e.getMessage().startsWith("task Mapper implements SurveyorI, whose @TaskInterface names 'Surveyor'"),
                e.getMessage());
    }

    @Test
    void describe_failsForASubclassTaskThatInheritsAnotherTasksInterface() {
        TaskDescriptionException e = assertThrows(TaskDescriptionException.class, () -> new FastExplorer().describe());
        assertTrue(e.getMessage().startsWith("task FastExplorer implements ExplorerI, whose @TaskInterface names 'Explorer'"),
                e.getMessage());
    }

    @Test
    void describe_failsWhenAnAnnotatedSuperinterfaceNamesAnotherTask() {
        TaskDescriptionException e = assertThrows(TaskDescriptionException.class, () -> TaskDescriber.describe(Drone.class));
        assertTrue(e.getMessage().startsWith("task Drone implements SurveyorI, whose @TaskInterface names 'Surveyor'"),
                e.getMessage());
    }

    // ---- events that cannot become event templates ----

    @Test
    void describe_failsWhenAnEventParameterHasNoName() {
        assumeFalse(BlindI.class.getMethods()[0].getParameters()[0].isNamePresent(), "compiled with -parameters");
        TaskDescriptionException e = assertThrows(TaskDescriptionException.class, () -> TaskDescriber.describe(Blind.class));
        assertEquals("event 'touched' of BlindI (task Blind): parameter 1 (double) has no attribute name;"
                + " annotate it @Attr(\"name\") (class files keep parameter names only when compiled with -parameters)",
                e.getMessage());
    }

    @Test
    void describe_failsWhenAnAttributeNameIsNotAnIdentifier() {
        TaskDescriptionException e = assertThrows(TaskDescriptionException.class, () -> TaskDescriber.describe(Odd.class));
        assertTrue(e.getMessage().startsWith("event 'seen' of OddNameI (task Odd): attribute name '2x' of parameter 1"
                + " is not a PonderTalk identifier"), e.getMessage());
    }

    @Test
    void describe_failsWhenAnAttributeNameRepeats() {
        TaskDescriptionException e = assertThrows(TaskDescriptionException.class, () -> TaskDescriber.describe(Twice.class));
        assertTrue(e.getMessage().startsWith("event 'seen' of TwiceI (task Twice): attribute 'x' appears twice"),
                e.getMessage());
    }

    @Test
    void describe_failsWhenTwoEventsShareANameWithDifferentAttributes() {
        TaskDescriptionException e = assertThrows(TaskDescriptionException.class, () -> TaskDescriber.describe(Overloaded.class));
        assertTrue(e.getMessage().startsWith("task Overloaded has two events named 'seen' with different attributes"),
                e.getMessage());
        assertTrue(e.getMessage().contains("[x double]") && e.getMessage().contains("[x double, y double]"), e.getMessage());
    }

    @Test
    void describe_failsWhenAnEventNameIsNotAnIdentifier() {
        TaskDescriptionException e = assertThrows(TaskDescriptionException.class, () -> TaskDescriber.describe(Dollar.class));
        assertTrue(e.getMessage().startsWith("event 'seen$now' of DollarI (task Dollar): its name is not a PonderTalk identifier"),
                e.getMessage());
    }

    @Test
    void isIdentifier_acceptsLettersThenLettersDigitsAndUnderscore() {
        assertTrue(TaskDescriber.isIdentifier("x_1Y"));
        assertTrue(!TaskDescriber.isIdentifier("_x") && !TaskDescriber.isIdentifier("1x") && !TaskDescriber.isIdentifier("")
                && !TaskDescriber.isIdentifier("é"));
    }
}
