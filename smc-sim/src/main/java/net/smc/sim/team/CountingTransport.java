package net.smc.sim.team;

import java.util.concurrent.atomic.AtomicLong;

import net.smc.core.transport.Address;
import net.smc.core.transport.ForwardingTransport;
import net.smc.core.transport.Receiver;
import net.smc.core.transport.Transport;

/**
 * Counts what a cell sends (datagrams, a broadcast once, and their bytes) into counters that
 * several cells may share; it sits under the cell's authentication, so it counts what goes on the
 * wire.
 */
public final class CountingTransport extends ForwardingTransport {
    private final AtomicLong datagrams;
    private final AtomicLong bytes;

    public CountingTransport(Transport inner, AtomicLong datagrams, AtomicLong bytes) {
        super(inner);
        this.datagrams = datagrams;
        this.bytes = bytes;
    }

    @Override
    public void send(Address to, byte[] data) {
        super.send(to, data);
        datagrams.incrementAndGet();
        bytes.addAndGet(data.length);
    }

    @Override
    public void broadcast(byte[] data) {
        super.broadcast(data);
        datagrams.incrementAndGet();
        bytes.addAndGet(data.length);
    }

    @Override
    public void setReceiver(Receiver receiver) {
        inner.setReceiver(receiver);
    }
}
