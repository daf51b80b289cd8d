package net.smc.core.comm;

import java.util.SplittableRandom;

import net.smc.core.transport.Address;
import net.smc.core.transport.Receiver;
import net.smc.core.transport.Transport;

/**
 * Test-only faults for a real transport, on the sending side: a seeded fraction of outgoing
 * datagrams is dropped, another duplicated, another held back until the next datagram has gone
 * (re-ordered). Loopback UDP loses nothing by itself, so this lets the fault suite run over real
 * sockets. Used on the cell's thread only, like the transport it wraps.
 */
final class FaultyTransport implements Transport {
    private final Transport inner;
    private final SplittableRandom random;
    private final double loss;
    private final double duplication;
    private final double reorder;
    private Address heldTo;
    private byte[] held;
    int dropped;

    FaultyTransport(Transport inner, long seed, double loss, double duplication, double reorder) {
        this.inner = inner;
        this.random = new SplittableRandom(seed);
        this.loss = loss;
        this.duplication = duplication;
        this.reorder = reorder;
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
        if (random.nextDouble() < loss) {
            dropped++;
            return;
        }
        if (held == null && random.nextDouble() < reorder) {
            held = data.clone();
            heldTo = to;
            return;
        }
        inner.send(to, data);
        if (random.nextDouble() < duplication) {
            inner.send(to, data);
        }
        if (held != null) {
            byte[] late = held;
            held = null;
            inner.send(heldTo, late);
        }
    }

    @Override
    public void broadcast(byte[] data) {
        inner.broadcast(data);
    }

    @Override
    public void setReceiver(Receiver receiver) {
        inner.setReceiver(receiver);
    }

    @Override
    public void close() {
        inner.close();
    }
}
