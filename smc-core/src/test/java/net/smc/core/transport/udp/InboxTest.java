package net.smc.core.transport.udp;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.List;
import java.util.Queue;
import net.smc.core.transport.Address;
import org.junit.jupiter.api.Test;

/** The two lanes between the event loop and the cell: session traffic first, strangers bounded. */
class InboxTest {
    private final Queue<Runnable> tasks = new ArrayDeque<>();
    private final UdpStats stats = new UdpStats();
    private final Inbox inbox = new Inbox(tasks::add, stats);
    private final List<String> heard = new ArrayList<>();

    private void runAll() {
        for (Runnable r; (r = tasks.poll()) != null; ) {
            r.run();
        }
    }

    private static Inbox.Datagram d(String text) {
        return new Inbox.Datagram(Address.loopback(1), text.getBytes());
    }

    @Test
    void urgentDatagramsGoBeforeAFloodOfOthers_andTheFloodIsBounded() {
        inbox.setReceiver((from, data) -> heard.add(new String(data)));
        inbox.setUrgent(data -> data[0] == 'U');
        List<Inbox.Datagram> flood = new ArrayList<>();
        for (int i = 0; i < 3_000; i++) {
            flood.add(d("stranger " + i));
        }
        inbox.received(flood);
        inbox.received(List.of(d("U heartbeat")));
        runAll();

        assertEquals("U heartbeat", heard.get(0), "session traffic is not queued behind strangers");
        assertEquals(Inbox.BULK_BACKLOG + 1, heard.size());
        assertEquals(3_000 - Inbox.BULK_BACKLOG, stats.droppedBacklog.sum());
    }

    @Test
    void strangersAreDeliveredAFewPerTurn_soOtherTasksOfTheCellInterleave() {
        inbox.setReceiver((from, data) -> heard.add(new String(data)));
        inbox.setUrgent(data -> false);
        List<Inbox.Datagram> flood = new ArrayList<>();
        for (int i = 0; i < 100; i++) {
            flood.add(d("stranger " + i));
        }
        inbox.received(flood);
        tasks.poll().run();
        assertEquals(Inbox.BULK_TURN, heard.size());
        assertEquals(1, tasks.size(), "the rest wait for the next turn");
        runAll();
        assertEquals(100, heard.size());
    }
}
