package net.smc.core.transport.udp;

import java.util.List;
import java.util.concurrent.Executor;
import java.util.concurrent.RejectedExecutionException;

import net.smc.core.transport.Address;
import net.smc.core.transport.Receiver;

import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Hands datagrams from the event loop to the cell: each is queued on the cell's (serial) executor
 * and given to the receiver there, unless the transport has closed in the meantime.
 */
final class Inbox {
    private static final Logger log = LoggerFactory.getLogger(Inbox.class);

    private final Executor cellExecutor;
    private final UdpStats stats;
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

    /** On the event loop: queue a burst of datagrams for the cell, as one task that delivers them in order. */
    void received(List<Datagram> burst) {
        try {
            cellExecutor.execute(() -> {
                for (Datagram d : burst) {
                    try {
                        deliver(d.from(), d.data());
                    } catch (RuntimeException e) {   // as if each datagram were a task of its own
                        log.error("the receiver failed on a datagram from {}; the cell goes on with the next", d.from(), e);
                    }
                }
            });
        } catch (RejectedExecutionException e) {
            stats.droppedRejected.add(burst.size());
            log.debug("{} datagram(s) from {} dropped: the cell's executor refused them", burst.size(),
                    burst.get(0).from(), e);
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
