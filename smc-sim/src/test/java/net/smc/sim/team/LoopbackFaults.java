package net.smc.sim.team;

import net.smc.core.host.CellHost;
import java.util.Collection;
import java.util.Map;
import java.util.Set;
import java.util.SplittableRandom;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.UnaryOperator;

import net.smc.core.host.CellHost;
import net.smc.core.transport.Address;
import net.smc.core.transport.ForwardingTransport;
import net.smc.core.transport.Receiver;
import net.smc.core.transport.Transport;

/**
 * Packet loss and partitions for one team of cells on loopback UDP, where the kernel loses nothing
 * and every socket hears every broadcast. Each cell's transport is wrapped ({@link #link}, given to
 * {@link CellHost.Settings#wrap}) in a decorator that consults this shared state:
 * <ul>
 *   <li>a partition cuts the team in two, a named side and everyone else (as
 *       {@code TeamSimulation.partition} does): a datagram from the other side is dropped on
 *       arrival, a unicast to the other side is not sent. Cells that join later are on the
 *       "everyone else" side;</li>
 *   <li>loss (none at first) drops each arriving datagram with the probability set, drawn from a
 *       seeded random per cell, so a broadcast is lost independently at each receiver.</li>
 * </ul>
 * The decorator sits under authentication, so what it drops is what a radio would lose. Changes
 * come from the test's thread; the decorators read them on the cells' threads.
 */
final class LoopbackFaults {
    private final Map<String, Address> addresses = new ConcurrentHashMap<>();
    private volatile double loss;
    private volatile Set<Address> side;

    /** Sets the probability that an arriving datagram is dropped, from now on (none at first). */
    void loss(double probability) {
        if (probability < 0 || probability > 1) {
            throw new IllegalArgumentException("loss " + probability + " is not a probability; it must be 0 to 1");
        }
        this.loss = probability;
    }

    /** The decorator for {@code vehicle}'s transport; its random choices come from {@code seed}. */
    UnaryOperator<Transport> link(String vehicle, long seed) {
        return inner -> {
            addresses.put(vehicle, inner.localAddress());
            return new Link(inner, new SplittableRandom(seed));
        };
    }

    /** Cuts {@code vehicles} off from everyone else (replacing any earlier partition). */
    void partition(Collection<String> vehicles) {
        side = vehicles.stream().map(v -> {
            Address a = addresses.get(v);
            if (a == null) {
                throw new IllegalArgumentException("vehicle '" + v + "' has no transport here (known: "
                        + addresses.keySet() + ")");
            }
            return a;
        }).collect(java.util.stream.Collectors.toUnmodifiableSet());
    }

    void heal() {
        side = null;
    }

    private boolean connected(Address a, Address b) {
        Set<Address> s = side;
        return s == null || s.contains(a) == s.contains(b);
    }

    /** One cell's transport with the team's faults applied. Used on that cell's thread only. */
    private final class Link extends ForwardingTransport {
        private final SplittableRandom random;

        Link(Transport inner, SplittableRandom random) {
            super(inner);
            this.random = random;
        }

        @Override
        public void send(Address to, byte[] data) {
            if (connected(inner.localAddress(), to)) {
                inner.send(to, data);
            }
        }

        @Override
        public void setReceiver(Receiver receiver) {
            inner.setReceiver((from, data) -> {
                double p = loss;
                if (connected(inner.localAddress(), from) && (p == 0 || random.nextDouble() >= p)) {
                    receiver.onDatagram(from, data);
                }
            });
        }
    }
}
