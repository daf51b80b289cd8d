package net.smc.core.transport.sim;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;

import net.smc.core.transport.Address;

/**
 * The partitions in force in an {@link InMemoryNetwork}. Each cuts every link between its two
 * sides, both ways; they add up until healed. Stored as pairs of sets, not as cut links, so
 * splitting a thousand nodes in two costs two sets, not half a million pairs.
 */
final class Partitions {
    private record Partition(Set<Address> a, Set<Address> b) {
        boolean separates(Address x, Address y) {
            return (a.contains(x) && b.contains(y)) || (b.contains(x) && a.contains(y));
        }
    }

    private final List<Partition> partitions = new ArrayList<>();

    void add(Set<Address> sideA, Set<Address> sideB) {
        Set<Address> a = new TreeSet<>(sideA);
        Set<Address> b = new TreeSet<>(sideB);
        if (a.isEmpty() || b.isEmpty()) {
            throw new IllegalArgumentException("partition " + a + " | " + b + " has an empty side; each side needs a node");
        }
        for (Address x : a) {
            if (b.contains(x)) {
                throw new IllegalArgumentException("partition sides overlap at " + x + "; a node may be on one side only");
            }
        }
        partitions.add(new Partition(a, b));
    }

    void healAll() {
        partitions.clear();
    }

    boolean separates(Address from, Address to) {
        for (Partition p : partitions) {
            if (p.separates(from, to)) {
                return true;
            }
        }
        return false;
    }
}
