package net.smc.policy;

import net.smc.policy.api.Diagnostic;
import net.smc.policy.api.AuthMode;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.math.BigDecimal;
import java.util.ArrayList;
import java.util.List;
import net.smc.policy.runtime.Domain;
import net.smc.policy.api.PonderError;
import org.junit.jupiter.api.Test;

/** The parts of the embedding API that the golden scripts cannot reach. */
class CellApiTest {
    private final List<String> reported = new ArrayList<>();

    private PolicyEngine cell(AuthMode mode) {
        return PolicyEngine.builder().auth(mode).errors(d -> reported.add(d.toString())).build();
    }

    @Test
    void runResult_carriesTheDiagnosticsOfItsOwnUnitOnly() {
        PolicyEngine cell = cell(AuthMode.OFF);
        cell.run("a.p2", "root frob.");
        RunResult second = cell.run("b.p2", "root print: 1. root bar.");
        assertEquals(List.of("b.p2:1:21: unknown operation 'bar' on SelfManagedCell"),
                second.diagnostics().stream().map(Diagnostic::toString).toList());
        assertEquals(2, reported.size(), "every diagnostic still reaches the reporter");
    }

    @Test
    void runResult_includesErrorsOfPoliciesTheUnitTriggered() {
        PolicyEngine cell = cell(AuthMode.OFF);
        cell.run("boot.p2", """
                root/event at: "go" put: (root/factory/event create: #()).
                p := root/factory/ecapolicy create. p event: root/event/go; action: [3 frob]; active: true.
                """);
        RunResult raised = cell.run("raise.p2", "root/event/go create.");
        assertEquals(RunResult.Status.OK, raised.status());
        assertEquals(List.of("boot.p2:2:72: ObligationPolicy: unhandled action error: unknown operation 'frob' on Number"),
                raised.diagnostics().stream().map(Diagnostic::toString).toList());
    }

    private static final String TWO_DOMAINS = """
            root at: "caller" put: root/factory/domain create.
            root at: "target" put: root/factory/domain create.
            """;

    @Test
    void sendAs_isCheckedFromTheGivenSubject() {
        PolicyEngine cell = cell(AuthMode.DENY);
        cell.run("boot.p2", TWO_DOMAINS);
        cell.endBoot();
        Object caller = cell.resolve("root/caller");
        Object target = cell.resolve("root/target");

        PonderError denied = assertThrows(PonderError.class, () -> cell.sendAs(caller, target, "at:put:", "k", 1));
        assertEquals("Ponder2AuthorizationException: at:put:", denied.getMessage());

        cell.run("allow.p2", "(root/factory/authpolicy subject: root/caller action: \"at:put:\" target: root/target focus: \"st\") active: true.");
        assertEquals(BigDecimal.ONE, cell.sendAs(caller, target, "at:put:", "k", 1));
        assertEquals(BigDecimal.ONE, ((Domain) target).get("k"));
    }

    @Test
    void sendAs_rootAsSubjectIsNeverChecked() {
        PolicyEngine cell = cell(AuthMode.DENY);
        cell.run("boot.p2", TWO_DOMAINS);
        cell.endBoot();
        cell.sendAs(cell.root(), cell.resolve("root/target"), "at:put:", "k", "v");
        assertEquals("v", ((Domain) cell.resolve("root/target")).get("k"));
    }

    @Test
    void sendAs_unknownSelectorIsAnErrorNamingIt() {
        PolicyEngine cell = cell(AuthMode.OFF);
        PonderError e = assertThrows(PonderError.class, () -> cell.sendAs(cell.root(), cell.root(), "frob"));
        assertEquals("unknown operation 'frob' on SelfManagedCell", e.getMessage());
    }

    @Test
    void creationListener_hearsOfEveryPolicyHoweverMade() {
        PolicyEngine cell = cell(AuthMode.ALLOW);
        List<Object> created = new ArrayList<>();
        java.util.function.Consumer<net.smc.policy.runtime.ManagedObject> listener = created::add;
        cell.runtime().listenCreations(listener);
        cell.run("make.p2", """
                a := root/factory/ecapolicy create.
                b := (root load: "ObligationPolicy") create.
                c := root/factory/authpolicy subject: root action: "*" target: root focus: "t".
                root at: "a" put: a. root at: "b" put: b. root at: "c" put: c.
                """);
        cell.runtime().unlistenCreations(listener);
        cell.run("after.p2", "root at: \"d\" put: root/factory/ecapolicy create.");
        assertEquals(List.of(cell.resolve("root/a"), cell.resolve("root/b"), cell.resolve("root/c")), created);
    }

    @Test
    void attachments_listTheNodesAPolicyIsAttachedTo() {
        PolicyEngine cell = cell(AuthMode.OFF);
        cell.run("make.p2", """
                root at: "d" put: root/factory/domain create.
                p := root/factory/ecapolicy create. root at: "p" put: p.
                p attach: root/d; active: true.
                """);
        var p = (net.smc.policy.runtime.ObligationPolicy) cell.resolve("root/p");
        assertEquals(List.of(cell.resolve("root/d")), p.attachments());
    }
}
