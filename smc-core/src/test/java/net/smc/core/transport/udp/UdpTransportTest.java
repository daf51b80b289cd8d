package net.smc.core.transport.udp;

import static java.nio.charset.StandardCharsets.UTF_8;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetSocketAddress;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.function.BooleanSupplier;

import net.smc.core.transport.Address;
import net.smc.core.transport.DatagramTooLargeException;
import net.smc.core.transport.QueueExecutor;
import net.smc.core.transport.Recorder;
import net.smc.core.transport.Signal;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/** What only the UDP transport does: filtering its own broadcasts, counters, binding, closing. */
class UdpTransportTest {
    private final Signal signal = new Signal();
    private final ExecutorService cells = Executors.newFixedThreadPool(2);
    private final UdpSettings settings = UdpSettings.defaults().withBroadcast("127.255.255.255", FreePort.udp());
    private final List<UdpTransport> opened = new ArrayList<>();

    @AfterEach
    void closeAll() {
        opened.forEach(UdpTransport::close);
        cells.shutdownNow();
    }

    private UdpTransport open(UdpSettings s, Recorder recorder) throws IOException {
        UdpTransport t = UdpTransport.open(s, cells);
        opened.add(t);
        if (recorder != null) {
            t.setReceiver(recorder);
        }
        return t;
    }

    private void await(BooleanSupplier done) throws InterruptedException {
        assertTrue(signal.await(done, UdpTransportContractTest.AWAIT_MILLIS), "hang guard");
    }

    @Test
    void ownBroadcast_comesBack_andIsCountedAsFiltered() throws Exception {
        Recorder ra = new Recorder(signal);
        Recorder rb = new Recorder(signal);
        UdpTransport a = open(settings, ra);
        UdpTransport b = open(settings, rb);

        a.broadcast("hello".getBytes(UTF_8));
        await(() -> rb.count() == 1);
        b.broadcast("marker".getBytes(UTF_8));   // reaches a's broadcast channel after a's own
        await(() -> ra.count() == 1);

        assertEquals(1, a.counters().ownBroadcastsFiltered());
        assertEquals(1, a.counters().broadcastsSent());
        assertEquals(1, a.counters().delivered());
    }

    @Test
    void wildcardBind_filtersItsOwnBroadcasts_andAdvertisesItsHost() throws Exception {
        Recorder ra = new Recorder(signal);
        Recorder rb = new Recorder(signal);
        UdpTransport a = open(settings.withBindHost("0.0.0.0", "127.0.0.1"), ra);
        UdpTransport b = open(settings, rb);

        a.broadcast("from everywhere".getBytes(UTF_8));
        await(() -> rb.count() == 1);
        b.broadcast("marker".getBytes(UTF_8));
        await(() -> ra.count() == 1);

        assertEquals(List.of(a.localAddress() + " from everywhere"), rb.received());
        assertEquals("127.0.0.1", a.localAddress().host());
        assertEquals(1, a.counters().ownBroadcastsFiltered());
    }

    @Test
    void oversizeDatagramFromTheWire_isDropped_andCounted() throws Exception {
        Recorder ra = new Recorder(signal);
        UdpTransport a = open(settings, ra);
        InetSocketAddress target = a.localAddress().toInetSocketAddress();

        try (DatagramSocket raw = new DatagramSocket(new InetSocketAddress("127.0.0.1", 0))) {
            raw.send(new DatagramPacket(new byte[3_000], 3_000, target));
            raw.send(new DatagramPacket("marker".getBytes(UTF_8), 6, target));   // same socket, same order
        }
        await(() -> ra.count() == 1);

        assertEquals(1, a.counters().droppedOversize());
        assertTrue(ra.received().get(0).endsWith(" marker"));
    }

    @Test
    void counters_countSendsAndRefusals() throws Exception {
        Recorder rb = new Recorder(signal);
        UdpTransport a = open(settings, null);
        UdpTransport b = open(settings, rb);

        a.send(b.localAddress(), "1".getBytes(UTF_8));
        a.send(b.localAddress(), "2".getBytes(UTF_8));
        assertThrows(DatagramTooLargeException.class, () -> a.send(b.localAddress(), new byte[2_000]));
        await(() -> rb.count() == 2);

        UdpCounters c = a.counters();
        assertEquals(2, c.sent());
        assertEquals(1, c.refusedOversize());
        assertEquals(0, c.sendFailures());
        assertEquals(2, b.counters().delivered());
    }

    @Test
    void datagramQueuedForTheCell_whenTheTransportCloses_isNotDelivered() throws Exception {
        QueueExecutor cell = new QueueExecutor(signal);
        Recorder rb = new Recorder(signal);
        UdpTransport a = open(settings, null);
        UdpTransport b = UdpTransport.open(settings, cell);
        opened.add(b);
        b.setReceiver(rb);

        a.send(b.localAddress(), "late".getBytes(UTF_8));
        await(() -> cell.size() == 1);
        b.close();
        cell.runQueued();

        assertEquals(0, rb.count());
        assertEquals(1, b.counters().droppedClosed());
    }

    @Test
    void bind_toATakenPort_failsNamingTheChannelAndAddress() throws Exception {
        try (DatagramSocket taken = new DatagramSocket(new InetSocketAddress("127.0.0.1", 0))) {
            int port = taken.getLocalPort();
            IOException e = assertThrows(IOException.class, () -> open(settings.withPort(port), null));
            assertTrue(e.getMessage().startsWith("cannot bind the unicast channel on 127.0.0.1:" + port + ": "), e.getMessage());
        }
    }

    @Test
    void close_releasesThePort_soANewCellCanBindIt() throws Exception {
        UdpTransport first = open(settings, null);
        int port = first.localAddress().port();
        first.close();

        UdpTransport second = open(settings.withPort(port), null);

        assertEquals(Address.loopback(port), second.localAddress());
    }

    @Test
    void close_ofATransportWithItsOwnLoop_shutsTheLoopDown() throws Exception {
        UdpTransport t = open(settings, null);
        t.close();
        t.close();
        assertTrue(t.loop().isShutDown());
    }

    @Test
    void close_ofATransportOnASharedLoop_leavesTheLoopRunning() throws Exception {
        try (UdpEventLoop loop = UdpEventLoop.create(1)) {
            UdpTransport t = UdpTransport.open(settings, cells, loop);
            t.close();

            UdpTransport next = UdpTransport.open(settings, cells, loop);
            next.close();
        }
    }

    @Test
    void open_onAClosedLoop_isRefused() {
        UdpEventLoop loop = UdpEventLoop.create(1);
        loop.close();
        IllegalStateException e = assertThrows(IllegalStateException.class, () -> UdpTransport.open(settings, cells, loop));
        assertEquals("the UDP event loop is closed; a transport cannot open on it", e.getMessage());
    }

    @Test
    void eventLoop_needsAThread() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> UdpEventLoop.create(0));
        assertEquals("an event loop needs 1 thread or more, not 0", e.getMessage());
    }
}
