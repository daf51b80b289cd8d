package net.smc.sim.task;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import net.smc.sim.map.OccupancyGrid;
import org.junit.jupiter.api.Test;

class BeaconAssistTest {

    @Test
    void beacon_raisesDistressWithPositionAndCondition_thenRepeatsEachPeriod() throws Exception {
        FakeWorld world = new FakeWorld(10, 10);
        Beacon beacon = new Beacon(world.robot("soldier", 6, 7, 0));
        EventLog log = new EventLog().watch(beacon);
        beacon.start();
        log.cell.run("call.p2", "root/task/Beacon period: 5; distress: \"wounded\".");
        log.assertNoErrors();
        List<String[]> calls = log.of("distress");
        assertEquals(1, calls.size());
        assertEquals(6.0, EventLog.num(calls.get(0)[0]));
        assertEquals(7.0, EventLog.num(calls.get(0)[1]));
        assertEquals("wounded", calls.get(0)[2]);
        world.run(11);
        assertEquals(3, log.of("distress").size());
        beacon.cancel();
        world.run(11);
        assertEquals(3, log.of("distress").size());
    }

    @Test
    void beacon_blankCondition_isRefused() {
        Beacon beacon = new Beacon(new FakeWorld(10, 10).robot("soldier", 6, 7, 0));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> beacon.raiseDistress(" "));
        assertTrue(e.getMessage().contains("condition must not be blank"), e.getMessage());
    }

    @Test
    void assist_raisesAssistedOnceTheNavigatorBringsTheRobotWithinReach() throws Exception {
        FakeWorld world = new FakeWorld(10, 10);
        FakeRobot rescuer = world.robot("r1", 2, 5, 0);
        Assist assist = new Assist(rescuer);
        Navigator nav = new Navigator(rescuer, new OccupancyGrid(0, 0, 10, 10, 0.25));
        EventLog log = new EventLog().watch(assist).watch(nav);
        assist.start();
        nav.start();
        log.cell.run("rescue.p2", """
                root/event at: "distress" put: (root/factory/event create: #("x" "y" "condition")).
                p := root/factory/ecapolicy create.
                p event: /event/distress; action: [:x :y :condition |
                    root/task/Assist assist: x y: y.
                    root/task/Navigator goTo: x - 0.8 y: y].
                p active: true.
                """);
        log.cell.raise("root/event/distress", 7, 5, "wounded");
        log.assertNoErrors();
        world.run(2);
        assertEquals(List.of(), log.of("assisted"));
        assertTrue(world.runUntil(assist::hasAssisted, 60));
        List<String[]> done = log.of("assisted");
        assertEquals(1, done.size());
        assertEquals(7.0, EventLog.num(done.get(0)[0]));
        assertTrue(Math.hypot(rescuer.x - 7, rescuer.y - 5) <= 1.0);
        world.run(5);
        assertEquals(1, log.of("assisted").size());
    }
}
