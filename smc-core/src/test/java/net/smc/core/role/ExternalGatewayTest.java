package net.smc.core.role;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.math.BigDecimal;
import java.util.List;
import net.smc.core.role.ExternalCallException.Kind;
import net.smc.policy.PolicyEngine;
import org.junit.jupiter.api.Test;

/**
 * Invocations through the external interface on behalf of other roles pass the receiving role's
 * authorisation policies, with deny when none applies; role-mission policies can change the
 * decision at run time.
 */
class ExternalGatewayTest {
    private static final TaskOperation GO_TO = new TaskOperation("Explorer", "goTo:");
    private static final TaskOperation VISITED = new TaskOperation("Explorer", "visited");
    private static final PolicySource AUTH = PolicySource.text("auth", """
            root/role/surveyor/peers at: "commander" put: root/factory/domain create.
            a := root/factory/authpolicy subject: root/role/surveyor/peers/commander action: "*"
                    target: root/role/surveyor/task focus: "st".
            root/role/surveyor/auth at: "commanderSteers" put: a.
            a := root/factory/authpolicy subject: root/role/surveyor/peers/commander action: "create:"
                    target: root/event/alarm focus: "st".
            root/role/surveyor/auth at: "commanderAlarms" put: a.
            a := root/factory/authpolicy subject: root/role/surveyor/policy action: "disable:"
                    target: root/role/surveyor focus: "st".
            root/role/surveyor/auth at: "missionControlsAuthorisations" put: a.
            """);
    /** On lowBattery, the surveyor stops taking orders from commanders; it prints every alarm. */
    private static final PolicySource MISSION = PolicySource.text("mission", """
            p := root/factory/ecapolicy create.
            p event: root/event/lowBattery; action: [root/role/surveyor disable: "commanderSteers"].
            root/role/surveyor/policy at: "saveBattery" put: p.
            p := root/factory/ecapolicy create.
            p event: root/event/alarm; action: [:level | root print: "alarm " + level].
            root/role/surveyor/policy at: "alarms" put: p.
            """);

    private final Fixture f = new Fixture(null, """
            root/event at: "lowBattery" put: (root/factory/event create).
            root/event at: "alarm" put: (root/factory/event create: #("level")).
            """);
    private final Explorer explorer = new Explorer();
    private final ExternalGateway gateway = new ExternalGateway(f.roles);
    private final Caller commander = new Caller("c7", "commander");
    private final Caller relay = new Caller("c9", "relay");

    ExternalGatewayTest() throws RoleLoadException {
        f.roles.load(Role.builder("surveyor").mission(MISSION).authorisation(AUTH).task("Explorer", () -> explorer)
                .local(new LocalInterface(List.of(GO_TO, VISITED), List.of()))
                .external(new ExternalInterface(List.of(GO_TO, VISITED), List.of(), List.of(), List.of("alarm")))
                .build());
    }

    @Test
    void exportedOperation_allowedForTheCaller_runs() throws Exception {
        gateway.invoke(commander, "surveyor", "goTo:", 5);

        assertEquals(List.of(BigDecimal.valueOf(5)), explorer.visited);
    }

    @Test
    void exportedOperation_answersItsResult() throws Exception {
        gateway.invoke(commander, "surveyor", "goTo:", 5);

        assertEquals(BigDecimal.ONE, gateway.invoke(commander, "surveyor", "visited"));
    }

    @Test
    void exportedOperation_withNoPolicyForTheCaller_isDenied() throws Exception {
        ExternalCallException e = assertThrows(ExternalCallException.class, () -> gateway.invoke(relay, "surveyor", "goTo:", 5));

        assertEquals(Kind.DENIED, e.kind());
        assertEquals("role 'relay' on cell 'c9' may not use operation 'goTo:' of task 'Explorer' of role 'surveyor':"
                + " denied by the authorisation policies of role 'surveyor' (Ponder2AuthorizationException: goTo:)", e.getMessage());
        assertEquals(List.of(), explorer.visited);
    }

    @Test
    void callerActsAsItsPeerSubject() throws Exception {
        gateway.invoke(commander, "surveyor", "goTo:", 5);

        assertEquals("<Peer root/role/surveyor/peers/commander/c7>", PolicyEngine.print(f.cell.resolve("root/role/surveyor/peers/commander/c7")));
    }

    @Test
    void roleMissionPolicy_disablingTheAuthorisation_deniesLaterCalls() throws Exception {
        gateway.invoke(commander, "surveyor", "goTo:", 1);

        f.cell.raise("root/event/lowBattery");
        ExternalCallException e = assertThrows(ExternalCallException.class, () -> gateway.invoke(commander, "surveyor", "goTo:", 2));

        assertEquals(Kind.DENIED, e.kind());
        assertEquals(List.of(BigDecimal.ONE), explorer.visited);
        assertTrue(f.errors.isEmpty(), f.errors::toString);
    }

    @Test
    void reenabledAuthorisation_allowsAgain() throws Exception {
        f.cell.raise("root/event/lowBattery");
        f.run("root/role/surveyor enable: \"commanderSteers\".");

        gateway.invoke(commander, "surveyor", "goTo:", 3);

        assertEquals(List.of(BigDecimal.valueOf(3)), explorer.visited);
    }

    @Test
    void operationNotExported_isRefusedBeforeAuthorisation() throws Exception {
        ExternalCallException e = assertThrows(ExternalCallException.class, () -> gateway.invoke(commander, "surveyor", "stop"));

        assertEquals(Kind.NOT_IN_INTERFACE, e.kind());
        assertEquals("operation 'stop' is not in the external interface of role 'surveyor' (it exports [goTo:, visited])", e.getMessage());
        assertTrue(explorer.isRunning());
    }

    @Test
    void managementOperation_isCheckedLikeAnyOther() throws Exception {
        ExternalCallException e = assertThrows(ExternalCallException.class, () -> gateway.invoke(commander, "surveyor", "policies"));

        assertEquals(Kind.DENIED, e.kind());
        assertTrue(e.getMessage().contains("management operation 'policies' of role 'surveyor'"), e.getMessage());
    }

    @Test
    void managementOperation_allowedByAPolicy_answers() throws Exception {
        f.run("""
                a := root/factory/authpolicy subject: root/role/surveyor/peers/commander action: "policies"
                        target: root/role/surveyor focus: "st".
                a active: true.
                """);

        Object answer = gateway.invoke(commander, "surveyor", "policies");

        assertEquals("[saveBattery, alarms]", PolicyEngine.print(answer));
    }

    @Test
    void requiredEvent_raisedByAnAllowedCaller_reachesTheRolesPolicies() throws Exception {
        gateway.raise(commander, "surveyor", "alarm", 4);

        assertEquals(List.of("alarm 4"), f.out);
    }

    @Test
    void requiredEvent_raisedByACallerWithoutPermission_isDenied() throws Exception {
        ExternalCallException e = assertThrows(ExternalCallException.class, () -> gateway.raise(relay, "surveyor", "alarm", 4));

        assertEquals(Kind.DENIED, e.kind());
        assertTrue(e.getMessage().contains("Ponder2AuthorizationException: create:"), e.getMessage());
        assertEquals(List.of(), f.out);
    }

    @Test
    void eventTheRoleDoesNotRequire_isRefused() throws Exception {
        ExternalCallException e = assertThrows(ExternalCallException.class,
                () -> gateway.raise(commander, "surveyor", "lowBattery"));

        assertEquals(Kind.NOT_IN_INTERFACE, e.kind());
        assertEquals("event 'lowBattery' is not required by role 'surveyor', so other roles may not raise it there"
                + " (it requires [alarm])", e.getMessage());
    }

    @Test
    void roleNotLoaded_isNamed() throws Exception {
        ExternalCallException e = assertThrows(ExternalCallException.class, () -> gateway.invoke(commander, "relay", "policies"));

        assertEquals(Kind.NO_SUCH_ROLE, e.kind());
        assertEquals("role 'relay' is not loaded on this cell", e.getMessage());
    }
}
