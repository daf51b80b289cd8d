package net.smc.core.team;

import java.util.ArrayList;
import java.util.List;
import net.smc.core.capability.CapabilitySummary;
import net.smc.core.mission.Mission;
import net.smc.core.mission.MissionRole;

/**
 * The test oracle: whether any assignment of roles to vehicles meets a mission's minimal
 * configuration, found by trying them all. A vehicle may hold any set of roles it meets the
 * requirements of and {@link Mission#allowsOnOneVehicle} allows; no role beyond its optimal
 * cardinality. Only for a handful of vehicles and roles.
 */
final class BruteForce {
    private final Mission mission;
    private final List<MissionRole> roles;
    private final List<List<Integer>> options = new ArrayList<>();
    private final int[] count;

    private BruteForce(Mission mission, List<CapabilitySummary> vehicles) {
        this.mission = mission;
        this.roles = mission.roles();
        this.count = new int[roles.size()];
        for (CapabilitySummary vehicle : vehicles) {
            List<Integer> sets = new ArrayList<>();
            for (int mask = 1; mask < 1 << roles.size(); mask++) {
                if (allowed(mask, vehicle)) {
                    sets.add(mask);
                }
            }
            options.add(sets);
        }
    }

    static boolean minimalPossible(Mission mission, List<CapabilitySummary> vehicles) {
        return new BruteForce(mission, vehicles).search(0);
    }

    private boolean allowed(int mask, CapabilitySummary vehicle) {
        List<String> held = new ArrayList<>();
        for (int r = 0; r < roles.size(); r++) {
            if ((mask & 1 << r) != 0) {
                if (!roles.get(r).requirement().isMetBy(vehicle)) {
                    return false;
                }
                held.add(roles.get(r).name());
            }
        }
        return mission.allowsOnOneVehicle(held);
    }

    private boolean search(int v) {
        if (met()) {
            return true;
        }
        if (v == options.size()) {
            return false;
        }
        if (search(v + 1)) {
            return true;
        }
        for (int mask : options.get(v)) {
            if (fits(mask)) {
                add(mask, 1);
                boolean found = search(v + 1);
                add(mask, -1);
                if (found) {
                    return true;
                }
            }
        }
        return false;
    }

    private boolean met() {
        for (int r = 0; r < roles.size(); r++) {
            if (count[r] < roles.get(r).minimal()) {
                return false;
            }
        }
        return true;
    }

    private boolean fits(int mask) {
        for (int r = 0; r < roles.size(); r++) {
            if ((mask & 1 << r) != 0 && count[r] + 1 > roles.get(r).optimal()) {
                return false;
            }
        }
        return true;
    }

    private void add(int mask, int delta) {
        for (int r = 0; r < roles.size(); r++) {
            if ((mask & 1 << r) != 0) {
                count[r] += delta;
            }
        }
    }
}
