package net.smc.core.transport.udp;

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

    /** On the event loop: queue the datagram for the cell. */
    void received(Address from, byte[] data) {
        try {
            cellExecutor.execute(() -> deliver(from, data));
        } catch (RejectedExecutionException e) {
            stats.droppedRejected.increment();
            log.debug("datagram from {} dropped: the cell's executor refused it", from, e);
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
