package net.smc.core.cell;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Collection;
import java.util.List;

/**
 * The order in which a manager puts several free vehicles that answered its discovery to its
 * policies, so that the managers of one role (siblings: they own the seats of the same roles below,
 * slot by slot, {@link Slots#owner}) begin with different vehicles.
 *
 * <p>Siblings hear the same free vehicles answer, in much the same order. Taken in that order,
 * every sibling began with the same vehicle, the quickest to answer: it took the first assignment to
 * reach it and refused the others, each refusal a round trip (and the policy files sent behind the
 * assignment) for nothing, and a lost refusal a retransmission timeout. Without a word between them,
 * the siblings agree on where each vehicle lies on a ring (a hash of its id, the same in every cell)
 * and each has its own share of the ring: the manager of sibling seat {@code i} of {@code M} the
 * share that begins at {@code i/M} of the way round. Each takes first the vehicles of its own share,
 * in ring order from its start: no sibling begins with them. However many of the vehicles a manager
 * heard (a vehicle taken stops answering), two siblings begin with the same one only when no vehicle
 * either heard lies in the share between them.
 *
 * <p>Shares hold unequal numbers of vehicles (each is where the hashes happen to fall), so some
 * siblings run short and take the spares of the others' shares. Taken in ring order, the spares
 * went to the short siblings in the same order: every short sibling whose own share ran out went
 * for the first spare after it, the one its neighbour on the ring went for too, and the one that
 * lost the race then for the next, again in step. Outside its own share a manager therefore puts
 * the vehicles in an order of its own, the vehicle's ring place mixed with its share's start: a
 * different order for each sibling, the same every time for one, so short siblings seldom go for
 * the same spare at once (on the set-up experiment's 1,000-role mission, about 15% fewer refused
 * assignments than in ring order). The policies still decide on every vehicle; only the order in
 * which they are asked changes.
 */
final class SiblingOrder {
    private SiblingOrder() {
    }

    /**
     * {@code vehicles} in the order the manager owning {@code openSeat} puts them to its policies.
     *
     * @param openSeat the manager's most important open seat: its owner is the manager's place among its siblings
     */
    static List<String> of(Collection<String> vehicles, Seat openSeat, Slots slots) {
        int siblings = slots.owner(openSeat).map(manager -> slots.optimal(manager.role())).orElse(1);
        long start = slots.owner(openSeat).map(manager -> startOf(manager.slot(), siblings)).orElse(Long.MIN_VALUE);
        long share = Long.divideUnsigned(-1L, Math.max(1, siblings));
        // Each vehicle's place is worked out once (a hash of its id), not at every comparison.
        List<Ranked> ranked = new ArrayList<>(vehicles.size());
        for (String v : vehicles) {
            long key = key(v);
            boolean own = siblings <= 1 || Long.compareUnsigned(key - start, share) < 0;
            ranked.add(new Ranked(v, own, own ? key - start : mix(key ^ start)));
        }
        ranked.sort(null);
        List<String> ordered = new ArrayList<>(ranked.size());
        ranked.forEach(r -> ordered.add(r.vehicle()));
        return ordered;
    }

    /**
     * A vehicle, whether it lies in the manager's own share, and its rank: in the own share its
     * distance round the ring from the share's start (unsigned), outside it its ring place mixed with
     * that start (signed).
     */
    private record Ranked(String vehicle, boolean own, long rank) implements Comparable<Ranked> {
        @Override
        public int compareTo(Ranked o) {
            int c;
            if (own != o.own) {
                c = own ? -1 : 1;
            } else {
                c = own ? Long.compareUnsigned(rank, o.rank) : Long.compare(rank, o.rank);
            }
            return c != 0 ? c : vehicle.compareTo(o.vehicle);
        }
    }

    /**
     * Whether {@code vehicle} lies in the share of the ring of the manager owning {@code openSeat}:
     * the share no sibling begins with. A manager without siblings owns the whole ring.
     */
    static boolean inOwnShare(String vehicle, Seat openSeat, Slots slots) {
        return slots.owner(openSeat).map(manager -> shareOf(vehicle, slots.optimal(manager.role())) == manager.slot())
                .orElse(true);
    }

    /** The sibling seat, of {@code siblings}, in whose share of the ring {@code vehicle} lies. */
    static int shareOf(String vehicle, int siblings) {
        if (siblings <= 1) {
            return 0;
        }
        long share = Long.divideUnsigned(-1L, siblings);
        return (int) Math.min(siblings - 1, Long.divideUnsigned(key(vehicle) - Long.MIN_VALUE, share));
    }

    /** Where the manager of sibling seat {@code slot} of {@code siblings} begins on the ring of keys: its own share's start. */
    static long startOf(int slot, int siblings) {
        long share = Long.divideUnsigned(-1L, Math.max(1, siblings));
        return Long.MIN_VALUE + share * slot;
    }

    /** The place of {@code vehicle} on the ring every cell agrees on: FNV-1a (64 bits) of its id's UTF-8 bytes, mixed. */
    static long key(String vehicle) {
        long h = 0xcbf29ce484222325L;
        for (byte b : vehicle.getBytes(StandardCharsets.UTF_8)) {
            h ^= b & 0xFF;
            h *= 0x100000001b3L;
        }
        // Ids that differ only in their last characters differ only in a few bits of FNV-1a: mix
        // them over all 64 bits (the finaliser of MurmurHash3), so that they spread round the ring.
        return mix(h);
    }

    /** The finaliser of MurmurHash3: every bit of {@code h} moves about half the bits of the result. */
    private static long mix(long h) {
        h ^= h >>> 33;
        h *= 0xff51afd7ed558ccdL;
        h ^= h >>> 33;
        h *= 0xc4ceb9fe1a85ec53L;
        h ^= h >>> 33;
        return h;
    }
}
