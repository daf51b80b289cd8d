package net.smc.core.transport.sim;

import java.util.Objects;

import net.smc.core.transport.Address;
import net.smc.core.transport.DatagramTooLargeException;
import net.smc.core.transport.Receiver;
import net.smc.core.transport.Transport;

/**
 * One node's endpoint on an {@link InMemoryNetwork}. Open until closed by its cell (then sending
 * fails) or crashed by the simulation (then sending is silently dropped and counted, as the cell
 * does not know it is dead).
 */
final class SimTransport implements Transport {
    private enum State { OPEN, CRASHED, CLOSED }

    private final InMemoryNetwork network;
    private final Address address;
    /** The network's counters of this address (kept across the node's lives), held here to save a look-up per datagram. */
    final Counters counters;
    /** The network's CPU of this address under a CPU model, once looked up; null before. */
    NodeCpu cpu;
    private Receiver receiver;
    private State state = State.OPEN;

    SimTransport(InMemoryNetwork network, Address address, Counters counters) {
        this.network = network;
        this.address = address;
        this.counters = counters;
    }

    @Override
    public Address localAddress() {
        return address;
    }

    @Override
    public void send(Address to, byte[] data) {
        Objects.requireNonNull(to, "to");
        checkCanSend(to, data);
        network.send(this, to, data.clone());
    }

    @Override
    public void broadcast(byte[] data) {
        checkCanSend(null, data);
        network.broadcast(this, data.clone());
    }

    @Override
    public long backlogMillis() {
        return network.backlogMillis(this);
    }

    @Override
    public void setReceiver(Receiver receiver) {
        Objects.requireNonNull(receiver, "receiver");
        if (this.receiver != null) {
            throw new IllegalStateException("transport " + address + " already has a receiver; it takes one");
        }
        this.receiver = receiver;
    }

    @Override
    public void close() {
        if (state == State.OPEN) {
            network.detach(this);
        }
        state = State.CLOSED;
    }

    boolean isCrashed() {
        return state == State.CRASHED;
    }

    boolean hasReceiver() {
        return receiver != null;
    }

    void crash() {
        state = State.CRASHED;
    }

    void deliver(Address from, byte[] data) {
        receiver.onDatagram(from, data);
    }

    private void checkCanSend(Address to, byte[] data) {
        Objects.requireNonNull(data, "data");
        if (state == State.CLOSED) {
            throw new IllegalStateException("transport " + address + " is closed; it cannot send");
        }
        DatagramTooLargeException.check(address, to, data.length);
    }

    @Override
    public String toString() {
        return "SimTransport[" + address + ", " + state + "]";
    }
}
