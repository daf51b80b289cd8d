package net.smc.core.host;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.DatagramSocket;
import java.net.InetSocketAddress;
import java.util.List;
import java.util.Set;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.locks.ReentrantLock;

import net.smc.core.capability.CapabilityDescription;
import net.smc.core.cell.CellEvent;
import net.smc.core.cell.Missions;
import net.smc.core.transport.Clock;
import net.smc.core.transport.udp.UdpSettings;
import org.junit.jupiter.api.Test;

/** What a host's settings add for a cell that shares a world: the guard lock, start hooks, a shared clock with a rate, counters. */
class CellHostSettingsTest {
    private static CellHost.Settings commander() {
        return CellHost.settings("cdr", Missions.reconnaissance(), CapabilityDescription.of("cdr", Set.of("communication"),
                List.of()), Missions.REPOSITORY).udp(UdpSettings.defaults().withBroadcast("127.255.255.255", freePort())).commander(true);
    }

    private static int freePort() {
        try (DatagramSocket probe = new DatagramSocket(new InetSocketAddress("0.0.0.0", 0))) {
            return probe.getLocalPort();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    @Test
    void guard_isHeldByTheStartHooks_theTrace_andCalls() throws Exception {
        ReentrantLock guard = new ReentrantLock();
        List<String> seen = new CopyOnWriteArrayList<>();
        CellHost.Settings s = commander().guard(guard)
                .beforeStart(c -> seen.add("before " + guard.isHeldByCurrentThread() + " " + c.vehicle()))
                .afterStart(c -> seen.add("after " + guard.isHeldByCurrentThread()))
                .trace(e -> seen.add("event " + guard.isHeldByCurrentThread()));
        try (CellHost host = CellHost.open(s)) {
            Thread.sleep(300);
            assertTrue(host.call(guard::isHeldByCurrentThread), "a call runs holding the guard");
            assertFalse(guard.isHeldByCurrentThread());
        }
        assertEquals("before true cdr", seen.get(0), seen.toString());
        assertTrue(seen.contains("after true"), seen.toString());
        assertTrue(seen.stream().anyMatch(l -> l.startsWith("event")), seen.toString());
        assertTrue(seen.stream().allMatch(l -> l.contains("true")), "every input held the guard: " + seen);
    }

    @Test
    void sharedClock_isTheCellsTime_andTheRateSpeedsItsTimers() throws Exception {
        long start = System.nanoTime();
        double rate = 20;
        Clock mission = () -> 1_000_000 + (long) ((System.nanoTime() - start) / 1e6 * rate);
        List<CellEvent> events = new CopyOnWriteArrayList<>();
        long fast;
        try (CellHost host = CellHost.open(commander().clock(mission, rate).trace(events::add))) {
            Thread.sleep(1_000);
            fast = host.udpCounters().broadcastsSent();
        }
        long real;
        try (CellHost host = CellHost.open(commander())) {
            Thread.sleep(1_000);
            real = host.udpCounters().broadcastsSent();
        }
        assertTrue(events.get(0).timeMillis() >= 1_000_000, "events carry the shared clock's time: " + events.get(0));
        assertTrue(fast >= 4 * Math.max(1, real), "broadcasts in 1 s of wall time at 20x: " + fast + ", at 1x: " + real);
    }
}
