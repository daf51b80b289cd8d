package net.smc.policy.runtime;

import net.smc.policy.api.Op;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import net.smc.policy.PolicyEngine;
import net.smc.policy.api.Diagnostic;
import net.smc.policy.RunResult;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * Operations declared by {@link Op} on the interfaces a managed class implements (the core's task
 * interfaces rely on it): found on direct and inherited interfaces, overridden by the class chain
 * and by more specific interfaces, ambiguous between unrelated interfaces.
 */
class InterfaceOpsTest {

    public interface Mover {
        @Op("moveTo:y:")
        void moveTo(double x, double y);

        @Op("where")
        String where();

        @Op("origin")
        static String origin() {
            return "0@0";
        }
    }

    /** Implements the interface's operations without annotating anything itself. */
    public static class Rover implements Mover {
        String at = "nowhere";

        @Override
        public void moveTo(double x, double y) {
            at = x + "@" + y;
        }

        @Override
        public String where() {
            return at;
        }
    }

    /** Gets {@link Mover} through its superclass. */
    public static class FastRover extends Rover {
    }

    /** Defines {@code where} itself: the class's operation wins over the interface's. */
    public static class Liar extends Rover {
        @Op("where")
        public String elsewhere() {
            return "not telling";
        }
    }

    /** Declares {@code where} on a superclass; the subclass adds an interface that also declares it. */
    public static class Base {
        @Op("where")
        public String base() {
            return "base";
        }
    }

    public interface Locator {
        @Op("where")
        String locate();
    }

    public static class Derived extends Base implements Locator {
        @Override
        public String locate() {
            return "locator";
        }
    }

    public interface Named {
        @Op("name")
        String name();
    }

    /** Redeclares {@code name} under the same selector: it is more specific than {@link Named}. */
    public interface Titled extends Named {
        @Op("name")
        String title();
    }

    /** Lists the general interface first, so the more specific one must still win. */
    public static class Knight implements Named, Titled {
        @Override
        public String name() {
            return "Lancelot";
        }

        @Override
        public String title() {
            return "Sir Lancelot";
        }
    }

    public interface Labelled {
        @Op("name")
        String label();
    }

    /** Gets {@code name} from two unrelated interfaces. */
    public static class Ambiguous implements Named, Labelled {
        @Override
        public String name() {
            return "a";
        }

        @Override
        public String label() {
            return "b";
        }
    }

    /** Resolves the ambiguity by defining the selector on the class. */
    public static class Resolved extends Ambiguous {
        @Op("name")
        public String chosen() {
            return "chosen";
        }
    }

    private final List<Diagnostic> errors = new ArrayList<>();
    private PolicyEngine cell;

    @BeforeEach
    void newCell() {
        cell = PolicyEngine.builder().errors(errors::add).build();
    }

    private String eval(Object object, String text) {
        cell.root().put("it", ManagedObject.wrap(object));
        RunResult result = cell.run("t.p2", text);
        assertEquals(List.of(), errors, "errors of " + text);
        assertEquals(RunResult.Status.OK, result.status(), text);
        return PolicyEngine.print(result.value());
    }

    @Test
    void interfaceOp_isInvokedOnTheImplementingObject() {
        Rover rover = new Rover();
        eval(rover, "it moveTo: 3 y: 4");
        assertEquals("3.0@4.0", rover.at);
        assertEquals("3.0@4.0", eval(rover, "it where"));
    }

    @Test
    void interfaceOp_isFoundThroughTheSuperclass() {
        assertEquals("nowhere", eval(new FastRover(), "it where"));
    }

    @Test
    void classOp_winsOverTheInterfaceOp() {
        assertEquals("not telling", eval(new Liar(), "it where"));
    }

    @Test
    void superclassOp_winsOverAnInterfaceOfTheSubclass() {
        assertEquals("base", eval(new Derived(), "it where"));
    }

    @Test
    void subinterfaceOp_winsOverTheInterfaceItExtends() {
        assertEquals("Sir Lancelot", eval(new Knight(), "it name"));
    }

    @Test
    void staticInterfaceMethods_areNotOperations() {
        assertFalse(ManagedClass.of(Rover.class).selectors().contains("origin"));
        assertTrue(ManagedClass.of(Rover.class).selectors().contains("moveTo:y:"));
    }

    @Test
    void sameSelectorFromUnrelatedInterfaces_isAnErrorNamingBoth() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> ManagedClass.of(Ambiguous.class));
        assertTrue(e.getMessage().contains("selector 'name'"), e.getMessage());
        assertTrue(e.getMessage().contains(Named.class.getName()), e.getMessage());
        assertTrue(e.getMessage().contains(Labelled.class.getName()), e.getMessage());
    }

    @Test
    void classOp_resolvesAnAmbiguityBetweenInterfaces() {
        assertEquals("chosen", eval(new Resolved(), "it name"));
    }
}
