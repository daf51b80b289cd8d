package net.smc.core.transport.sim;

import static java.nio.charset.StandardCharsets.UTF_8;

import java.util.ArrayList;
import java.util.List;

import net.smc.core.transport.Address;
import net.smc.core.transport.Transport;

/** A simulated network for tests: nodes that record "time from text" lines, and a trace of the network's events. */
final class SimFixture {
    final SimulationScheduler scheduler = new SimulationScheduler();
    final InMemoryNetwork network;
    final List<String> trace = new ArrayList<>();

    SimFixture(long seed) {
        network = new InMemoryNetwork(scheduler, seed);
        network.addObserver(new NetworkObserver() {
            @Override
            public void delivered(long atMillis, Address from, Address to, byte[] data) {
                trace.add(atMillis + " deliver " + from + " -> " + to + " " + new String(data, UTF_8));
            }

            @Override
            public void dropped(long atMillis, Address from, Address to, DropReason reason, byte[] data) {
                trace.add(atMillis + " drop " + reason + " " + from + " -> " + to + " " + new String(data, UTF_8));
            }
        });
    }

    /** A node with a receiver that records what arrives. */
    final class Node {
        final Transport transport;
        final List<String> received = new ArrayList<>();

        Node(Transport transport) {
            this.transport = transport;
            transport.setReceiver((from, data) ->
                    received.add(scheduler.nowMillis() + " " + from.port() + " " + new String(data, UTF_8)));
        }

        Address address() {
            return transport.localAddress();
        }

        void send(Node to, String text) {
            transport.send(to.address(), text.getBytes(UTF_8));
        }

        void broadcast(String text) {
            transport.broadcast(text.getBytes(UTF_8));
        }

        NodeCounters counters() {
            return network.counters(address());
        }
    }

    Node node(int port) {
        return new Node(network.attach(Address.loopback(port)));
    }

    void runUntilIdle() {
        scheduler.runUntilIdle(1_000_000);
    }
}
