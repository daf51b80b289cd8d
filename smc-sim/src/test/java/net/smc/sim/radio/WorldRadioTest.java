package net.smc.sim.radio;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;

import net.smc.core.transport.Address;
import net.smc.core.transport.Transport;
import net.smc.core.transport.sim.InMemoryNetwork;
import net.smc.core.transport.sim.SimulationScheduler;
import net.smc.sim.robot.KoalaSpec;
import net.smc.sim.robot.SimRobot;
import net.smc.sim.arena.Arena;
import net.smc.sim.world.SimWorld;
import net.smc.sim.world.Worlds;
import org.junit.jupiter.api.Test;

class WorldRadioTest {
    private static final RadioSettings SHORT = new RadioSettings(8, 0.3, 0.1, false);

    private static SimWorld world(Arena arena, SimulationScheduler scheduler) {
        return SimWorld.builder(arena, scheduler).seed(9).radio(SHORT).build();
    }

    @Test
    void linksBreakAsRobotsMoveApart_andHealAsTheyComeBack() {
        SimWorld world = world(Worlds.arena(30, 6, "<start id='s0' x='1' y='1'/>"), new SimulationScheduler());
        SimRobot still = world.addRobot("still", Worlds.start(2, 3, 0), KoalaSpec.koala());
        SimRobot mover = world.addRobot("mover", Worlds.start(3, 3, 0), KoalaSpec.koala().withOdometryNoise(0));
        double[] speed = {0.6};
        mover.control(this, (t, dt) -> mover.drive().setWheelSpeeds(speed[0], speed[0]));
        List<Boolean> linked = new ArrayList<>();
        double previous = 2;
        boolean falling = true;
        for (int i = 0; i < 4_000; i++) {
            world.step();
            double q = still.radio().linkQuality("mover");
            if (i % 50 == 0) {
                linked.add(q > 0);
            }
            if (mover.pose().x() > 14) {
                speed[0] = -0.6;
            }
            if (speed[0] > 0 && q > 0) {
                falling &= q <= previous;
                previous = q;
            }
            assertEquals(q, mover.radio().linkQuality("still"), 0, "links are symmetric");
        }
        assertTrue(falling, "quality falls with distance");
        int breaks = 0;
        int heals = 0;
        for (int i = 1; i < linked.size(); i++) {
            breaks += linked.get(i - 1) && !linked.get(i) ? 1 : 0;
            heals += !linked.get(i - 1) && linked.get(i) ? 1 : 0;
        }
        assertEquals(1, breaks, linked.toString());
        assertEquals(1, heals, linked.toString());
        assertTrue(linked.get(linked.size() - 1));
    }

    @Test
    void wallsAttenuate_andEnoughOfThemBreakALink() {
        String starts = "<start id='s0' x='1' y='1'/>";
        Arena open = Worlds.arena(12, 6, starts);
        Arena oneWall = Worlds.arena(12, 6, starts + "<wall x1='4' y1='0' x2='4' y2='6'/>");
        Arena twoWalls = Worlds.arena(12, 6, starts + "<wall x1='4' y1='0' x2='4' y2='6'/><wall x1='5' y1='0' x2='5' y2='6'/>");
        double[] q = new double[3];
        Arena[] arenas = {open, oneWall, twoWalls};
        for (int i = 0; i < 3; i++) {
            SimWorld world = world(arenas[i], new SimulationScheduler());
            world.addRobot("a", Worlds.start(2, 3, 0), KoalaSpec.koala());
            world.addRobot("b", Worlds.start(7, 3, 0), KoalaSpec.koala());
            q[i] = world.radio().quality("a", "b");
        }
        double expectedOpen = 1 - Math.pow(5.0 / 8, 4);
        assertEquals(expectedOpen, q[0], 1e-9);
        assertEquals(expectedOpen * 0.3, q[1], 1e-9);
        assertEquals(0, q[2], "0.8 * 0.09 is under the 0.1 minimum");
    }

    @Test
    void asRadioModel_deliversWithTheLinksQuality_andNotAtAllFromADisabledRobot() {
        SimulationScheduler scheduler = new SimulationScheduler();
        SimWorld world = world(Worlds.arena(12, 6, "<start id='s0' x='1' y='1'/><station id='cdr' x='1' y='5'/>"), scheduler);
        SimRobot a = world.addRobot("a", Worlds.start(2, 3, 0), KoalaSpec.koala());
        world.addRobot("b", Worlds.start(9, 3, 0), KoalaSpec.koala());
        Address addressA = Address.loopback(4001);
        Address addressB = Address.loopback(4002);
        Address cdr = Address.loopback(4000);
        Address stranger = Address.loopback(4999);
        world.radio().bind(addressA, "a");
        world.radio().bind(addressB, "b");
        world.radio().bind(cdr, "cdr");
        double q = world.radio().quality("a", "b");
        assertTrue(q > 0.3 && q < 0.5, "7 m of 8: " + q);

        InMemoryNetwork network = new InMemoryNetwork(scheduler, 5);
        network.setRadio(world.radio());
        Transport ta = network.attach(addressA);
        Transport tb = network.attach(addressB);
        int[] received = new int[1];
        tb.setReceiver((from, data) -> received[0]++);
        ta.setReceiver((from, data) -> { });
        int sent = 4_000;
        for (int i = 0; i < sent; i++) {
            ta.send(addressB, new byte[] {1});
        }
        scheduler.runFor(1_000);
        assertEquals(q, received[0] / (double) sent, 0.03, "delivered share");
        assertTrue(world.radio().reachable(cdr, addressA));
        assertFalse(world.radio().reachable(stranger, addressA), "unbound nodes are out of the world here");

        a.disable("test");
        world.step();
        assertEquals(0, world.radio().quality("a", "b"));
        int before = received[0];
        for (int i = 0; i < 100; i++) {
            ta.send(addressB, new byte[] {1});
        }
        scheduler.runFor(1_000);
        assertEquals(before, received[0], "a disabled robot's radio is silent");
        assertTrue(network.counters(addressB).droppedByRadio() >= 100);
    }

    @Test
    void linksHoldBetweenRefreshes_andFollowThePositionsAtEachRefresh() {
        SimWorld world = world(Worlds.arena(30, 6, "<start id='s0' x='1' y='1'/>"), new SimulationScheduler());
        SimRobot still = world.addRobot("still", Worlds.start(2, 3, 0), KoalaSpec.koala());
        SimRobot mover = world.addRobot("mover", Worlds.start(3, 3, 0), KoalaSpec.koala());
        mover.control(this, (t, dt) -> mover.drive().setWheelSpeeds(0.4, 0.4));
        int every = world.radio().refreshSteps();
        assertEquals(5, every, "100 ms of 20 ms steps");
        int changes = 0;
        double previous = world.radio().quality("still", "mover");
        for (int i = 0; i < 500; i++) {
            world.step();
            double q = world.radio().quality("still", "mover");
            double d = Math.hypot(mover.x() - still.x(), mover.y() - still.y());
            double now = 1 - Math.pow(d / SHORT.range(), 4);
            if (world.steps() % every == 0) {
                assertEquals(now, q, 1e-12, "at a refresh the link is that of the positions then");
            } else {
                assertEquals(previous, q, 0, "between refreshes the link holds (step " + world.steps() + ")");
            }
            changes += q != previous ? 1 : 0;
            previous = q;
        }
        assertTrue(changes >= 500 / every - 2, "the moving robot's link changed at the refreshes: " + changes);
    }

    @Test
    void aRefreshOfOneStep_isThePerStepModel() {
        SimWorld world = SimWorld.builder(Worlds.arena(30, 6, "<start id='s0' x='1' y='1'/><wall x1='6' y1='0' x2='6' y2='4'/>"),
                new SimulationScheduler()).seed(9).radio(SHORT.withRefreshMillis(1)).build();
        SimRobot still = world.addRobot("still", Worlds.start(2, 1, 0), KoalaSpec.koala());
        SimRobot mover = world.addRobot("mover", Worlds.start(3, 5, 0), KoalaSpec.koala());
        mover.control(this, (t, dt) -> mover.drive().setWheelSpeeds(0.5, 0.5));
        assertEquals(1, world.radio().refreshSteps());
        boolean sawWall = false;
        for (int i = 0; i < 600; i++) {
            world.step();
            double d = Math.hypot(mover.x() - still.x(), mover.y() - still.y());
            int walls = world.wallsBetween(still.x(), still.y(), mover.x(), mover.y());
            double expected = Math.max(0, 1 - Math.pow(d / SHORT.range(), 4)) * Math.pow(SHORT.wallFactor(), walls);
            expected = expected < SHORT.minQuality() ? 0 : expected;
            assertEquals(expected, world.radio().quality("still", "mover"), 1e-12, "step " + world.steps());
            sawWall |= walls > 0 && expected > 0;
        }
        assertTrue(sawWall, "the link passed through the wall at some point");
    }

    @Test
    void aDisabledRobotFallsSilentAtOnce_notAtTheNextRefresh() {
        SimWorld world = world(Worlds.arena(12, 6, "<start id='s0' x='1' y='1'/>"), new SimulationScheduler());
        SimRobot a = world.addRobot("a", Worlds.start(2, 3, 0), KoalaSpec.koala());
        world.addRobot("b", Worlds.start(5, 3, 0), KoalaSpec.koala());
        world.step();
        assertTrue(world.radio().quality("a", "b") > 0);
        assertTrue(world.steps() % world.radio().refreshSteps() != 0, "between refreshes");
        a.disable("test");
        assertEquals(0, world.radio().quality("a", "b"));
        assertEquals(0, world.radio().quality("b", "a"));
        assertTrue(world.radio().view("b").neighbours().isEmpty());
    }

    @Test
    void aRobotDisabledBeforeTheRadioFirstHeardOfIt_isSilent() {
        SimWorld world = world(Worlds.arena(12, 6, "<start id='s0' x='1' y='1'/>"), new SimulationScheduler());
        world.addRobot("a", Worlds.start(2, 3, 0), KoalaSpec.koala()).disable("test");
        world.addRobot("b", Worlds.start(5, 3, 0), KoalaSpec.koala());
        assertEquals(0, world.radio().quality("a", "b"));
        assertEquals(0, world.radio().quality("b", "a"));
    }

    @Test
    void refreshOutOfRange_isRefusedNamingTheSetting() {
        IllegalArgumentException e = org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class,
                () -> SHORT.withRefreshMillis(0));
        assertTrue(e.getMessage().contains("refreshMillis 0") && e.getMessage().contains("1 to 60000"), e.getMessage());
    }
}
