package net.smc.core.role;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** The checks a role description makes when it is built. */
class RoleTest {
    private static final TaskOperation GO_TO = new TaskOperation("Explorer", "goTo:");

    @Test
    void roleName_mustBeADomainName() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Role.builder("hazard-detector").build());

        assertEquals("role name is 'hazard-detector'; it must be one or more ASCII letters, digits or _"
                + " (it becomes a domain entry)", e.getMessage());
    }

    @Test
    void policyListedTwice_isRefused() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Role.builder("surveyor")
                .mission("policy:/roles/surveyor/mission").authorisation("policy:/roles/surveyor/mission").build());

        assertEquals("policy 'policy:/roles/surveyor/mission' is listed twice in role 'surveyor';"
                + " each policy file is loaded once per role", e.getMessage());
    }

    @Test
    void policyUri_mustNameARepositoryFile() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> PolicySource.uri("roles/surveyor"));

        assertEquals("policy URI 'roles/surveyor' must start with 'policy:/' and name a file", e.getMessage());
    }

    @Test
    void taskListedTwice_isRefused() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Role.builder("surveyor")
                .task("Explorer", Explorer::new).task("Explorer", Explorer::new).build());

        assertEquals("task 'Explorer' is listed twice in role 'surveyor'", e.getMessage());
    }

    @Test
    void roleManagingItself_isRefused() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> Role.builder("surveyor").manages("surveyor").build());

        assertEquals("role 'surveyor' cannot manage itself", e.getMessage());
    }

    @Test
    void exportedOperation_mustBeInTheLocalInterface() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Role.builder("surveyor")
                .task("Explorer", Explorer::new)
                .external(new ExternalInterface(List.of(GO_TO), List.of(), List.of(), List.of())).build());

        assertEquals("exported operation 'goTo:' of task 'Explorer' is not in the local interface of role 'surveyor';"
                + " a role exports only its tasks' operations", e.getMessage());
    }

    @Test
    void localOperation_mustNameATaskOfTheRole() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Role.builder("surveyor")
                .local(new LocalInterface(List.of(GO_TO), List.of())).build());

        assertEquals("local operation 'goTo:' of role 'surveyor' names task 'Explorer', which is not one of the role's"
                + " tasks []", e.getMessage());
    }

    @Test
    void publishedEvent_mustBeInTheLocalInterface() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Role.builder("hdetector")
                .external(new ExternalInterface(List.of(), List.of("hazardDetected"), List.of(), List.of())).build());

        assertEquals("published event 'hazardDetected' is not in the local interface of role 'hdetector';"
                + " a role publishes only events raised inside it", e.getMessage());
    }

    @Test
    void exportedSelector_mustBeUnique() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new ExternalInterface(
                List.of(GO_TO, new TaskOperation("Other", "goTo:")), List.of(), List.of(), List.of()));

        assertEquals("operation 'goTo:' is exported twice; a caller names an operation by its selector alone,"
                + " so it must be unique", e.getMessage());
    }

    @Test
    void exportedSelector_mustNotShadowAManagementOperation() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new ExternalInterface(
                List.of(new TaskOperation("Explorer", "name")), List.of(), List.of(), List.of()));

        assertEquals("exported operation 'name' of task 'Explorer' has the name of a management operation common"
                + " to all roles; rename it", e.getMessage());
    }

    @Test
    void unmetRequirements_nameTheMissingRoleOrOperation() {
        Role detector = Role.builder("hdetector").external(new ExternalInterface(List.of(), List.of(),
                List.of(new RequiredOperation("aggregator", "addHazard:"), new RequiredOperation("surveyor", "goTo:")),
                List.of())).build();
        Role aggregator = Role.builder("aggregator").build();

        assertEquals(List.of("role 'hdetector' requires 'addHazard:' of role 'aggregator', which does not export it",
                "role 'hdetector' requires 'goTo:' of role 'surveyor', which is not in the team"),
                detector.unmetRequirements(Map.of("aggregator", aggregator, "hdetector", detector)));
    }

    @Test
    void unmetRequirements_emptyWhenAnotherRoleExportsIt() {
        Role surveyor = Role.builder("surveyor").task("Explorer", Explorer::new)
                .local(new LocalInterface(List.of(GO_TO), List.of()))
                .external(new ExternalInterface(List.of(GO_TO), List.of(), List.of(), List.of())).build();
        Role commander = Role.builder("commander").external(new ExternalInterface(List.of(), List.of(),
                List.of(new RequiredOperation("surveyor", "goTo:")), List.of())).build();

        assertEquals(List.of(), commander.unmetRequirements(Map.of("surveyor", surveyor)));
    }
}
