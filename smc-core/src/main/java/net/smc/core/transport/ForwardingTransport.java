package net.smc.core.transport;

import java.util.Objects;

/**
 * A {@link Transport} that decorates another: it sends through it and closes it, and leaves to the
 * subclass what happens to arriving datagrams (it takes the inner transport's receiver). The base of
 * the decorators that sit between a cell and its network: status queries, simulated authentication.
 */
public abstract class ForwardingTransport implements Transport {
    /** The decorated transport. */
    protected final Transport inner;

    protected ForwardingTransport(Transport inner) {
        this.inner = Objects.requireNonNull(inner, "inner");
    }

    @Override
    public Address localAddress() {
        return inner.localAddress();
    }

    @Override
    public int datagramCapacity() {
        return inner.datagramCapacity();
    }

    @Override
    public void send(Address to, byte[] data) {
        inner.send(to, data);
    }

    @Override
    public void broadcast(byte[] data) {
        inner.broadcast(data);
    }

    @Override
    public long backlogMillis() {
        return inner.backlogMillis();
    }

    @Override
    public void close() {
        inner.close();
    }
}
