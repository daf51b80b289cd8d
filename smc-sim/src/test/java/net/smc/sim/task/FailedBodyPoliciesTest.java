package net.smc.sim.task;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import net.smc.core.discovery.CredentialCheck;
import net.smc.core.discovery.DiscoveryObject;
import net.smc.core.role.Caller;
import net.smc.core.role.ExternalCallException;
import net.smc.core.role.ExternalGateway;
import net.smc.core.role.ExternalInterface;
import net.smc.core.role.LocalInterface;
import net.smc.core.role.Role;
import net.smc.core.role.RoleManager;
import net.smc.policy.PolicyEngine;
import net.smc.policy.RunResult;
import net.smc.policy.api.ArrayValue;
import net.smc.policy.api.AuthMode;
import net.smc.policy.api.Diagnostic;
import net.smc.policy.api.Managed;
import net.smc.policy.api.Op;
import net.smc.policy.api.PolicyRepository;
import net.smc.sim.map.OccupancyGrid;
import net.smc.sim.map.Point;
import org.junit.jupiter.api.Test;

/**
 * The reconnaissance's policies about a failed teammate's body, loaded from the repository with
 * their authorisations into a deny-by-default cell holding a surveyor and a detector (as a
 * surveyor's vehicle does in the minimal configuration): on the failure of a vehicle the surveyor
 * manages, the body's position goes to the surveyor's Explorer and the detector's HazardDetector and
 * is published as failedBody; a failedBody from another surveyor does the same here; other roles
 * may not raise it.
 */
class FailedBodyPoliciesTest {
    /** root/team: records what the policies publish. */
    @Managed("Team")
    public static final class Team {
        final List<String> raised = new ArrayList<>();

        @Op("raise:values:")
        public int raise(String event, ArrayValue values) {
            raised.add(event + " " + values.items());
            return 1;
        }
    }

    private final List<String> out = new ArrayList<>();
    private final List<Diagnostic> errors = new ArrayList<>();
    private final Team team = new Team();
    private final FakeWorld world = new FakeWorld(20, 14);
    private final FakeRobot robot = world.robot("s1", 3, 7, 0);
    private final Explorer explorer = new Explorer(robot, new OccupancyGrid(0, 0, 20, 14, 0.25));
    private final HazardDetector detector = new HazardDetector(robot, new OccupancyGrid(0, 0, 20, 14, 0.25));
    private final PolicyEngine cell;
    private final RoleManager roles;

    FailedBodyPoliciesTest() throws Exception {
        PolicyRepository repository = new PolicyRepository(Path.of(System.getProperty("smc.repo.dir", "../policies")));
        cell = PolicyEngine.builder().repository(repository).auth(AuthMode.DENY).output(out::add).errors(errors::add).build();
        RunResult boot = cell.load("policy:/boot/events");
        assertTrue(boot.ok() && boot.diagnostics().isEmpty(), () -> "boot events: " + boot.diagnostics());
        cell.root().put("team", PolicyEngine.manage(team));
        new DiscoveryObject(CredentialCheck.sharedToken("team7"), (uav, role) -> { }).install(cell);
        cell.endBoot();
        roles = RoleManager.builder(cell).reassignment((manager, role, scheme) -> { }).build();
        roles.load(Role.builder("surveyor").mission("policy:/roles/surveyor/mission", "policy:/roles/surveyor/survey")
                .authorisation("policy:/roles/surveyor/auth", "policy:/roles/surveyor/surveyAuth")
                .task("Explorer", () -> explorer).manages("hdetector", "relay")
                .local(new LocalInterface(List.of(), List.of("targetSighted", "mapUpdate", "failedBody")))
                .external(new ExternalInterface(List.of(), List.of("targetSighted", "mapUpdate", "failedBody"), List.of(),
                        List.of("hazardDetected", "mapUpdate", "failedBody"))).build());
        roles.load(Role.builder("hdetector").mission("policy:/roles/hdetector/mission", "policy:/roles/hdetector/detect")
                .authorisation("policy:/roles/hdetector/auth", "policy:/roles/hdetector/detectAuth")
                .task("HazardDetector", () -> detector)
                .local(new LocalInterface(List.of(), List.of("hazardDetected")))
                .external(new ExternalInterface(List.of(), List.of("hazardDetected"), List.of(),
                        List.of("targetSighted", "mapUpdate", "failedBody"))).build());
        assertEquals(List.of(), errors);
    }

    private List<Point> explorerBodies() {
        return explorer.bodies();
    }

    @Test
    void theFailureOfAManagedVehicle_tellsTheExplorerAndTheDetector_andPublishesTheBody() {
        assertTrue(cell.raise("/event/UAVFailure", "UAVFailure", "hdetector", "d2",
                List.of(6.25, 2.5)), errors::toString);

        assertEquals(List.of(), errors);
        assertEquals(List.of(new Point(6.25, 2.5)), explorerBodies(), "the surveyor's Explorer");
        assertEquals(List.of(new Point(6.25, 2.5)), detector.bodies(), "the detector's HazardDetector");
        assertEquals(List.of("failedBody [failedBody, d2, 6.25, 2.5]"), team.raised, "published for the other robots");
        assertTrue(out.contains("may push d2 aside at 6.25,2.5"), out::toString);
    }

    @Test
    void aBodyAnotherSurveyorTellsOf_isPushedAsideHere_once() throws Exception {
        ExternalGateway gateway = new ExternalGateway(roles);
        gateway.raise(new Caller("c2", "surveyor"), "surveyor", "failedBody", "failedBody", "d2", 7, 5.9);
        gateway.raise(new Caller("c2", "surveyor"), "surveyor", "failedBody", "failedBody", "d2", 7, 5.9);

        assertEquals(List.of(), errors);
        assertEquals(List.of(new Point(7, 5.9)), explorerBodies());
        assertEquals(List.of(new Point(7, 5.9)), detector.bodies());
        assertEquals(1, out.stream().filter(l -> l.startsWith("may push d2")).count(), "remembered once: " + out);
        assertEquals(List.of(), team.raised, "what others tell of is not published again at once");
    }

    @Test
    void onlySurveyorsMayTellOfABody() {
        ExternalGateway gateway = new ExternalGateway(roles);
        assertThrows(ExternalCallException.class,
                () -> gateway.raise(new Caller("c5", "relay"), "hdetector", "failedBody", "failedBody", "d2", 7, 5.9));
        assertEquals(List.of(), detector.bodies());
    }
}
