package net.smc.sim.experiment;

import java.util.Optional;

/**
 * One role of a generated mission: its name, its level in the distributed tree, how many seats it
 * has, the role that manages it there, and the resource a vehicle needs to hold it.
 *
 * @param name     the role name ({@code b3l2}: branch 3, level 2)
 * @param level    its depth in the distributed management tree, 1 or more
 * @param seats    its minimal and optimal cardinality
 * @param manager  the role that manages it in the distributed scheme ({@code commander} at level 1)
 */
public record RoleType(String name, int level, int seats, String manager) {

    /** The resource only vehicles built for this role have. */
    public String resource() {
        return "kit_" + name;
    }

    /** The id of the vehicle built for slot {@code slot} of this role. */
    public String vehicle(int slot) {
        return name + "n" + slot;
    }

    /** The role type a generated vehicle id names, if it is one ({@code b3l2n7} is role {@code b3l2}). */
    static Optional<String> roleOfVehicle(String vehicle) {
        int n = vehicle.lastIndexOf('n');
        return n > 0 && vehicle.startsWith("b") ? Optional.of(vehicle.substring(0, n)) : Optional.empty();
    }
}
