package net.smc.policy;

import net.smc.policy.api.PolicyRepository;
import net.smc.policy.api.Diagnostic;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.math.BigDecimal;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import net.smc.policy.api.DomainHandle;
import net.smc.policy.api.Handle;
import net.smc.policy.api.Op;
import org.junit.jupiter.api.Test;

/** The embedding examples of the README and of {@link PolicyEngine}'s javadoc, run as written there. */
class EmbeddingExampleTest {

    /** A managed object an application provides: PonderTalk sees its annotated methods. */
    public static final class Thermometer {
        private double celsius = 21.5;

        @Op("create")
        public Thermometer() {
        }

        @Op("celsius")
        public double celsius() {
            return celsius;
        }

        @Op("set:")
        public void set(double value) {
            celsius = value;
        }
    }

    @Test
    void readmeExample_runsPolicyAndManagedObject() {
        List<String> lines = new ArrayList<>();
        List<Diagnostic> errors = new ArrayList<>();
        PolicyEngine cell = PolicyEngine.builder()
                .output(lines::add)
                .errors(errors::add)
                .register("Thermometer", Thermometer.class)
                .build();
        cell.run("boot.p2", """
                root at: "t" put: (root load: "Thermometer") create.
                root/event at: "alarm" put: (root/factory/event create: #("level")).
                p := root/factory/ecapolicy create.
                p event: root/event/alarm;
                  condition: [:level | level > 5];
                  action: [:level | root/t set: level. root print: "set to " + root/t celsius].
                p active: true.
                """);
        cell.raise("root/event/alarm", 7);
        cell.raise("root/event/alarm", 3);

        assertEquals(List.of("set to 7.0"), lines);
        assertTrue(errors.isEmpty(), errors::toString);
        DomainHandle root = cell.root();
        assertEquals(7.0, ((Thermometer) ((Handle) root.get("t")).impl()).celsius());
    }

    @Test
    void cellJavadocExample_printsTheLevel() {
        List<String> lines = new ArrayList<>();
        PolicyEngine cell = PolicyEngine.builder().output(lines::add).build();
        cell.run("boot.p2", """
                root/event at: "alarm" put: (root/factory/event create: #("level")).
                p := root/factory/ecapolicy create.
                p event: root/event/alarm; condition: [:level | level > 5]; action: [:level | root print: level].
                p active: true.
                """);
        cell.raise("root/event/alarm", 7);
        assertEquals(List.of("7"), lines);
    }

    @Test
    void repositoryExample_loadsByUri() {
        List<String> lines = new ArrayList<>();
        List<Diagnostic> errors = new ArrayList<>();
        Path repo = Path.of(System.getProperty("smc.repo.dir", "../policies"));
        PolicyEngine cell = PolicyEngine.builder().output(lines::add).errors(errors::add).repository(new PolicyRepository(repo)).build();

        RunResult result = cell.load("policy:/examples/alarm");

        assertTrue(result.ok(), () -> result + " " + errors);
        assertEquals(List.of("alarm boiler at level 7", "alarm valve at level 9", "[boiler, valve]"), lines);
        assertEquals(new BigDecimal("9"), ((DomainHandle) cell.resolve("root/log")).get("valve"));
    }
}
