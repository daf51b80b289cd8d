package net.smc.core.team;

import java.util.ArrayList;
import java.util.Collection;
import java.util.Comparator;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import net.smc.core.capability.CapabilityRequirement;
import net.smc.core.capability.CapabilitySummary;
import net.smc.core.mission.MissionRole;

/**
 * The vehicles a planner works with, sorted by id (so that ties always break the same way), and
 * for each the bitset of roles whose requirement it meets. Requirements are compiled once into
 * bit masks over the resource and task names the mission mentions, so that checking 1,000
 * vehicles against 100 roles is a few mask operations per pair, not set look-ups. Vehicles with the
 * same role bitset share a capability class: the search treats them as interchangeable.
 */
final class Fleet {
    final String[] ids;
    /** For each vehicle, the roles it may hold. */
    final long[][] capable;
    /** For each vehicle, how many roles it may hold: the fewer, the sooner it is used. */
    final int[] flexibility;
    /** For each vehicle, its capability class (equal role bitsets, equal class). */
    final int[] classOf;
    private final Map<String, Integer> index = new HashMap<>();
    private final int classCount;

    /**
     * @throws IllegalArgumentException when two vehicles have the same id
     */
    Fleet(RoleTable roles, Collection<CapabilitySummary> vehicles) {
        List<CapabilitySummary> sorted = new ArrayList<>(vehicles);
        sorted.sort(Comparator.comparing(CapabilitySummary::vehicle));
        int n = sorted.size();
        ids = new String[n];
        capable = new long[n][];
        flexibility = new int[n];
        classOf = new int[n];
        // Each resource and task a requirement names gets a bit; a vehicle's other names do not matter.
        Map<String, Integer> resourceBits = new HashMap<>();
        Map<String, Integer> taskBits = new HashMap<>();
        for (MissionRole role : roles.mission.roles()) {
            role.requirement().resources().forEach(s -> resourceBits.putIfAbsent(s, resourceBits.size()));
        }
        for (MissionRole role : roles.mission.roles()) {
            role.requirement().tasks().forEach(s -> taskBits.putIfAbsent(s, resourceBits.size() + taskBits.size()));
        }
        int nameWords = Math.max(1, (resourceBits.size() + taskBits.size() + 63) / 64);
        long[][] needs = new long[roles.size()][];
        for (int r = 0; r < roles.size(); r++) {
            CapabilityRequirement requirement = roles.mission.roles().get(r).requirement();
            long[] need = new long[nameWords];
            requirement.resources().forEach(s -> BitArrays.set(need, resourceBits.get(s)));
            requirement.tasks().forEach(s -> BitArrays.set(need, taskBits.get(s)));
            needs[r] = need;
        }
        Map<Key, Integer> classes = new HashMap<>();
        for (int v = 0; v < n; v++) {
            CapabilitySummary vehicle = sorted.get(v);
            ids[v] = vehicle.vehicle();
            if (index.put(ids[v], v) != null) {
                throw new IllegalArgumentException("two vehicles are called '" + ids[v] + "'; vehicle ids are unique");
            }
            long[] has = new long[nameWords];
            vehicle.resources().forEach(s -> mark(has, resourceBits.get(s)));
            vehicle.tasks().forEach(s -> mark(has, taskBits.get(s)));
            capable[v] = new long[roles.words];
            for (int r = 0; r < roles.size(); r++) {
                if (covers(has, needs[r])) {
                    BitArrays.set(capable[v], r);
                }
            }
            flexibility[v] = BitArrays.count(capable[v]);
            classOf[v] = classes.computeIfAbsent(new Key(capable[v]), k -> classes.size());
        }
        classCount = classes.size();
    }

    /** A role bitset as a map key (an array's own equals is identity). */
    private record Key(long[] bits) {
        @Override
        public boolean equals(Object other) {
            return other instanceof Key key && java.util.Arrays.equals(bits, key.bits);
        }

        @Override
        public int hashCode() {
            return java.util.Arrays.hashCode(bits);
        }
    }

    private static void mark(long[] has, Integer bit) {
        if (bit != null) {
            BitArrays.set(has, bit);
        }
    }

    private static boolean covers(long[] has, long[] need) {
        for (int i = 0; i < need.length; i++) {
            if ((need[i] & ~has[i]) != 0) {
                return false;
            }
        }
        return true;
    }

    /** How many capability classes there are; class ids are 0 to this, exclusive. */
    int classCount() {
        return classCount;
    }

    int size() {
        return ids.length;
    }

    boolean capable(int v, int r) {
        return BitArrays.get(capable[v], r);
    }

    /** The vehicle with id {@code id}, or -1. */
    int indexOf(String id) {
        return index.getOrDefault(id, -1);
    }
}
