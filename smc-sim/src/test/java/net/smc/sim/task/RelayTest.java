package net.smc.sim.task;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;

class RelayTest {

    @Test
    void lowQuality_theRelaySearchesItsWayBackIntoRange_andReportsBothCrossings() throws Exception {
        FakeWorld world = new FakeWorld(20, 20);
        FakeRobot base = world.robot("base", 2, 10, 0);
        FakeRobot relay = world.robot("r1", 10, 10, 0);
        Relay task = new Relay(relay);
        EventLog log = new EventLog().watch(task);
        task.start();
        log.cell.run("keep.p2", "root/task/Relay keep: \"base\"; threshold: 0.5.");
        log.assertNoErrors();
        assertTrue(world.runUntil(() -> relay.radio().linkQuality("base") >= 0.55, 300),
                "quality " + relay.radio().linkQuality("base"));
        double distance = Math.hypot(relay.x - base.x, relay.y - base.y);
        assertTrue(distance <= 4.5, "distance " + distance);
        List<String[]> events = log.of("linkQuality");
        assertTrue(events.size() >= 2, "events: " + log.lines);
        assertEquals("base", events.get(0)[1], "the far end");
        assertTrue(EventLog.num(events.get(0)[2]) < 0.5, "first report below the threshold");
        assertTrue(EventLog.num(events.get(events.size() - 1)[2]) >= 0.5, "last report above it");
        world.run(5);
        assertEquals(0, relay.speed(), 1e-9, "it stops once the link is good");
    }

    @Test
    void knownPeerPosition_theRelayHeadsStraightForIt() throws Exception {
        FakeWorld world = new FakeWorld(20, 20);
        world.robot("base", 2, 10, 0);
        FakeRobot relay = world.robot("r1", 10, 10, Math.PI / 2);
        Relay task = new Relay(relay);
        task.peerAt("base", 2, 10);
        task.start();
        assertTrue(world.runUntil(() -> relay.radio().linkQuality("base") >= 0.55, 60));
        assertEquals(10, relay.y, 0.5, "it went straight along y = 10");
    }

    @Test
    void goodQuality_theRelayStaysPut() {
        FakeWorld world = new FakeWorld(20, 20);
        world.robot("base", 2, 10, 0);
        FakeRobot relay = world.robot("r1", 4, 10, 0);
        Relay task = new Relay(relay);
        task.keep("base");
        task.start();
        world.run(5);
        assertEquals(4, relay.x, 1e-9);
    }
}
