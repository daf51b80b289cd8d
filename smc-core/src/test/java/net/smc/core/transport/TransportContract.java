package net.smc.core.transport;

import static java.nio.charset.StandardCharsets.UTF_8;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.BooleanSupplier;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * The behaviour every {@link Transport} must have, run against each implementation by a subclass
 * that supplies a {@link Net}. Nothing here sleeps: a test waits for datagrams through
 * {@link Net#awaitUntil}, which runs the simulation or, for real UDP, waits with a generous hang
 * guard. Absence is shown with a marker: a datagram that, on a correct transport, arrives after the
 * one that must not.
 */
public abstract class TransportContract {

    /** Endpoints on one network (simulated or real) and a way to let their datagrams travel. */
    protected interface Net extends AutoCloseable {
        /** A new open endpoint. */
        Transport open();

        /** Lets datagrams travel until {@code done} holds; fails the test if it does not in time. */
        void awaitUntil(BooleanSupplier done);

        /** Closes every endpoint and frees what the network holds. */
        @Override
        void close();
    }

    protected final Signal signal = new Signal();
    private Net net;

    /** The network under test; {@link #signal} is to be told of every arrival (the recorders do). */
    protected abstract Net newNet();

    @BeforeEach
    final void openNet() {
        net = newNet();
    }

    @AfterEach
    final void closeNet() {
        net.close();
    }

    private Transport open(Recorder recorder) {
        Transport t = net.open();
        t.setReceiver(recorder);
        return t;
    }

    private static byte[] bytes(String text) {
        return text.getBytes(UTF_8);
    }

    @Test
    void unicast_arrivesWithTheSendersAddress() {
        Recorder ra = new Recorder(signal);
        Recorder rb = new Recorder(signal);
        Transport a = open(ra);
        Transport b = open(rb);

        a.send(b.localAddress(), bytes("hello"));

        net.awaitUntil(() -> rb.count() == 1);
        assertEquals(List.of(a.localAddress() + " hello"), rb.received());
        assertEquals(0, ra.count());
    }

    @Test
    void unicast_replyToTheSourceAddress_reachesTheSender() {
        Recorder ra = new Recorder(signal);
        Transport a = open(ra);
        Transport b = net.open();
        b.setReceiver((from, data) -> b.send(from, bytes("re: " + new String(data, UTF_8))));

        a.send(b.localAddress(), bytes("ping"));

        net.awaitUntil(() -> ra.count() == 1);
        assertEquals(List.of(b.localAddress() + " re: ping"), ra.received());
    }

    @Test
    void unicast_toItself_isDelivered() {
        Recorder ra = new Recorder(signal);
        Transport a = open(ra);

        a.send(a.localAddress(), bytes("note to self"));

        net.awaitUntil(() -> ra.count() == 1);
        assertEquals(List.of(a.localAddress() + " note to self"), ra.received());
    }

    @Test
    void broadcast_reachesEveryOtherNode_butNotTheSender() {
        Recorder ra = new Recorder(signal);
        Recorder rb = new Recorder(signal);
        Recorder rc = new Recorder(signal);
        Transport a = open(ra);
        Transport b = open(rb);
        Transport c = open(rc);

        a.broadcast(bytes("discovery"));
        net.awaitUntil(() -> rb.count() == 1 && rc.count() == 1);
        // Marker: b's broadcast reaches a by the same path a's own broadcast would have taken, later.
        b.broadcast(bytes("marker"));
        net.awaitUntil(() -> ra.count() == 1 && rc.count() == 2);

        assertEquals(List.of(a.localAddress() + " discovery"), rb.received());
        assertEquals(List.of(a.localAddress() + " discovery", b.localAddress() + " marker"), rc.received());
        assertEquals(List.of(b.localAddress() + " marker"), ra.received());
    }

    @Test
    void close_stopsDelivery() {
        Recorder ra = new Recorder(signal);
        Recorder rb = new Recorder(signal);
        Recorder rc = new Recorder(signal);
        Transport a = open(ra);
        Transport b = open(rb);
        open(rc);
        Address bAddress = b.localAddress();

        b.close();
        a.send(bAddress, bytes("to the closed one"));
        a.broadcast(bytes("to all"));
        net.awaitUntil(() -> rc.count() == 1);

        assertEquals(0, rb.count());
    }

    @Test
    void send_afterClose_fails() {
        Transport a = open(new Recorder(signal));
        Address self = a.localAddress();
        a.close();

        IllegalStateException e = assertThrows(IllegalStateException.class, () -> a.send(self, bytes("x")));
        assertEquals("transport " + self + " is closed; it cannot send", e.getMessage());
        assertThrows(IllegalStateException.class, () -> a.broadcast(bytes("x")));
    }

    @Test
    void close_twice_isHarmless() {
        Transport a = open(new Recorder(signal));
        a.close();
        a.close();
    }

    @Test
    void send_ofMoreThanTheLimit_isRefused() {
        Transport a = open(new Recorder(signal));
        Transport b = open(new Recorder(signal));

        DatagramTooLargeException e = assertThrows(DatagramTooLargeException.class,
                () -> a.send(b.localAddress(), new byte[Transport.MAX_DATAGRAM_BYTES + 1]));
        assertEquals("datagram of 1401 bytes from " + a.localAddress() + " to " + b.localAddress()
                + " refused: a datagram may carry at most 1400 bytes", e.getMessage());
        assertEquals(1401, e.length());
    }

    @Test
    void broadcast_ofMoreThanTheLimit_isRefused() {
        Transport a = open(new Recorder(signal));

        DatagramTooLargeException e = assertThrows(DatagramTooLargeException.class,
                () -> a.broadcast(new byte[Transport.MAX_DATAGRAM_BYTES + 1]));
        assertEquals("datagram of 1401 bytes from " + a.localAddress()
                + " to broadcast refused: a datagram may carry at most 1400 bytes", e.getMessage());
    }

    @Test
    void send_ofExactlyTheLimit_arrivesWhole() {
        Transport a = open(new Recorder(signal));
        Transport b = net.open();
        AtomicReference<byte[]> got = new AtomicReference<>();
        b.setReceiver((from, data) -> {
            got.set(data);
            signal.changed();
        });
        byte[] data = new byte[Transport.MAX_DATAGRAM_BYTES];
        for (int i = 0; i < data.length; i++) {
            data[i] = (byte) i;
        }

        a.send(b.localAddress(), data);

        net.awaitUntil(() -> got.get() != null);
        assertArrayEquals(data, got.get());
    }

    @Test
    void send_copiesTheData_soTheCallerMayReuseTheArray() {
        Recorder rb = new Recorder(signal);
        Transport a = open(new Recorder(signal));
        Transport b = open(rb);
        byte[] data = bytes("first");

        a.send(b.localAddress(), data);
        System.arraycopy(bytes("XXXXX"), 0, data, 0, 5);

        net.awaitUntil(() -> rb.count() == 1);
        assertEquals(List.of(a.localAddress() + " first"), rb.received());
    }

    @Test
    void setReceiver_twice_isRefused() {
        Transport a = open(new Recorder(signal));

        IllegalStateException e = assertThrows(IllegalStateException.class, () -> a.setReceiver((from, data) -> { }));
        assertEquals("transport " + a.localAddress() + " already has a receiver; it takes one", e.getMessage());
    }

    /** Four senders at once towards one receiver; the receiver must never be entered twice at the same time. */
    @Test
    void receiver_runsOneCallAtATime() {
        int senders = 4;
        int each = 250;
        AtomicInteger inside = new AtomicInteger();
        AtomicInteger overlaps = new AtomicInteger();
        AtomicInteger received = new AtomicInteger();
        Transport target = net.open();
        target.setReceiver((from, data) -> {
            if (inside.incrementAndGet() != 1) {
                overlaps.incrementAndGet();
            }
            for (int spin = 0; spin < 1_000; spin++) {
                Thread.onSpinWait();   // widen the window in which an overlap would show
            }
            inside.decrementAndGet();
            received.incrementAndGet();
            signal.changed();
        });
        Transport[] from = new Transport[senders];
        for (int s = 0; s < senders; s++) {
            from[s] = open(new Recorder(signal));
        }

        for (int i = 0; i < each; i++) {
            for (Transport sender : from) {
                sender.send(target.localAddress(), bytes("n" + i));
            }
        }

        // Depends on loopback UDP not losing 1,000 small datagrams (see manyMessages_eachWay_allArrive).
        net.awaitUntil(() -> received.get() == senders * each);
        assertEquals(0, overlaps.get());
    }

    /**
     * A thousand datagrams each way between two endpoints all arrive (in any order). On real UDP
     * this depends on loopback not losing datagrams, which holds in practice while the receive
     * buffer (1 MiB by default) holds the burst; the wait is bounded by the network's hang guard.
     */
    @Test
    void manyMessages_eachWay_allArrive() {
        int count = 1_000;
        Recorder ra = new Recorder(signal);
        Recorder rb = new Recorder(signal);
        Transport a = open(ra);
        Transport b = open(rb);

        for (int i = 0; i < count; i++) {
            a.send(b.localAddress(), bytes("a" + i));
            b.send(a.localAddress(), bytes("b" + i));
        }

        net.awaitUntil(() -> ra.count() >= count && rb.count() >= count);
        Set<String> expectedAtB = new TreeSet<>();
        Set<String> expectedAtA = new TreeSet<>();
        for (int i = 0; i < count; i++) {
            expectedAtB.add(a.localAddress() + " a" + i);
            expectedAtA.add(b.localAddress() + " b" + i);
        }
        assertEquals(expectedAtB, new TreeSet<>(rb.received()));
        assertEquals(expectedAtA, new TreeSet<>(ra.received()));
        assertEquals(count, ra.count(), "no duplicates at a");
        assertEquals(count, rb.count(), "no duplicates at b");
    }

    @Test
    void localAddress_differsBetweenEndpoints() {
        Transport a = net.open();
        Transport b = net.open();
        assertTrue(!a.localAddress().equals(b.localAddress()), a.localAddress() + " twice");
    }
}
