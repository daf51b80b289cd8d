package net.smc.core.transport.udp;

import java.util.List;
import java.util.Queue;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Predicate;
import java.util.concurrent.Executor;
import java.util.concurrent.RejectedExecutionException;

import net.smc.core.transport.Address;
import net.smc.core.transport.Receiver;

import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Hands datagrams from the event loop to the cell, in two lanes. Datagrams the {@code urgent}
 * predicate picks (for an authenticated cell: the traffic of established sessions, whose checks
 * cost a MAC) go first; the rest (strangers' signed datagrams, whose checks cost a signature) wait
 * in a queue of at most {@value #BULK_BACKLOG}, beyond which the newest are dropped and counted,
 * and are delivered at most {@value #BULK_TURN} per turn of the cell's executor, so that a flood of
 * them neither grows without bound nor delays the cell's own traffic, timers and commands. Each
 * turn runs on the cell's (serial) executor, unless the transport has closed in the meantime.
 */
final class Inbox {
    static final int BULK_BACKLOG = 1024;
    static final int BULK_TURN = 32;
    private static final Logger log = LoggerFactory.getLogger(Inbox.class);

    private final Executor cellExecutor;
    private final UdpStats stats;
    private final Queue<Datagram> urgentLane = new ConcurrentLinkedQueue<>();
    private final Queue<Datagram> bulkLane = new ConcurrentLinkedQueue<>();
    private final AtomicInteger bulkQueued = new AtomicInteger();
    private final AtomicBoolean turnQueued = new AtomicBoolean();
    private volatile Predicate<byte[]> urgent = data -> true;
    private volatile Receiver receiver;
    private volatile boolean closed;

    Inbox(Executor cellExecutor, UdpStats stats) {
        this.cellExecutor = cellExecutor;
        this.stats = stats;
    }

    /** Whether a receiver was set before; sets it if not. */
    synchronized boolean setReceiver(Receiver r) {
        if (receiver != null) {
            return false;
        }
        receiver = r;
        return true;
    }

    void setUrgent(Predicate<byte[]> urgent) {
        this.urgent = urgent;
    }

    void close() {
        closed = true;
    }

    /** One datagram copied out of Netty: its source and payload. */
    record Datagram(Address from, byte[] data) {
    }

    /** On the event loop: queue the datagram for the cell. */
    void received(Address from, byte[] data) {
        received(List.of(new Datagram(from, data)));
    }

    /** On the event loop: queue a burst of datagrams for the cell, each in its lane, in arrival order within a lane. */
    void received(List<Datagram> burst) {
        Predicate<byte[]> isUrgent = urgent;
        for (Datagram d : burst) {
            if (isUrgent.test(d.data())) {
                urgentLane.add(d);
            } else if (bulkQueued.incrementAndGet() <= BULK_BACKLOG) {
                bulkLane.add(d);
            } else {
                bulkQueued.decrementAndGet();
                stats.droppedBacklog.increment();
            }
        }
        queueTurn();
    }

    private void queueTurn() {
        if (!turnQueued.compareAndSet(false, true)) {
            return;
        }
        try {
            cellExecutor.execute(this::turn);
        } catch (RejectedExecutionException e) {
            int dropped = drop(urgentLane) + drop(bulkLane);
            bulkQueued.set(0);
            stats.droppedRejected.add(dropped);
            log.debug("{} datagram(s) dropped: the cell's executor refused them", dropped, e);
        }
    }

    /** On the cell's thread: every urgent datagram, then a share of the bulk, then another turn if any remain. */
    private void turn() {
        turnQueued.set(false);
        for (Datagram d; (d = urgentLane.poll()) != null; ) {
            deliverSafely(d);
        }
        for (int i = 0; i < BULK_TURN; i++) {
            Datagram d = bulkLane.poll();
            if (d == null) {
                break;
            }
            bulkQueued.decrementAndGet();
            deliverSafely(d);
            Datagram first = urgentLane.poll();   // session traffic that arrived meanwhile goes before the next stranger
            if (first != null) {
                deliverSafely(first);
            }
        }
        if (!urgentLane.isEmpty() || !bulkLane.isEmpty()) {
            queueTurn();
        }
    }

    private static int drop(Queue<Datagram> lane) {
        int n = 0;
        while (lane.poll() != null) {
            n++;
        }
        return n;
    }

    private void deliverSafely(Datagram d) {
        try {
            deliver(d.from(), d.data());
        } catch (RuntimeException e) {   // as if each datagram were a task of its own
            log.error("the receiver failed on a datagram from {}; the cell goes on with the next", d.from(), e);
        }
    }

    /** On the cell's thread. */
    private void deliver(Address from, byte[] data) {
        Receiver r = receiver;
        if (closed) {
            stats.droppedClosed.increment();
            log.debug("datagram of {} bytes from {} dropped: the transport is closed", data.length, from);
        } else if (r == null) {
            stats.droppedNoReceiver.increment();
            log.debug("datagram of {} bytes from {} dropped: no receiver is set yet", data.length, from);
        } else {
            stats.delivered.increment();
            r.onDatagram(from, data);
        }
    }
}
