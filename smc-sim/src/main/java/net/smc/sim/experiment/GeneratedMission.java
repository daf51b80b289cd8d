package net.smc.sim.experiment;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

import net.smc.core.cell.Scheme;
import net.smc.sim.team.SimVehicle;

/**
 * A mission written by {@link MissionGenerator}: its files, its roles and a team of vehicles that
 * fills every seat, one vehicle per seat (and spares, if asked for), each able to hold exactly its own role.
 *
 * @param directory  where it was written: {@code missions/} and {@code policies/} (the repository)
 * @param shape      the shape of its management tree
 * @param roles      its roles but the commander, level by level
 */
public record GeneratedMission(Path directory, TreeShape shape, List<RoleType> roles) {
    /** The commander's vehicle id. */
    public static final String COMMANDER = "cdr";
    /** The most spare vehicles {@link #vehicles(int)} builds, in percent of a role's seats. */
    public static final int MAX_SPARE_PERCENT = 1_000;

    public GeneratedMission {
        roles = List.copyOf(roles);
    }

    /** The policy repository: {@code boot/} and {@code roles/ROLE/{mission,auth}.p2}. */
    public Path repository() {
        return directory.resolve("policies");
    }

    public Path classFile() {
        return directory.resolve("missions").resolve("generated.class.xml");
    }

    /** The instance of the scheme: the same roles, the scheme parameter and the commander's policies differ. */
    public Path instanceFile(Scheme scheme) {
        return directory.resolve("missions").resolve("generated-" + MissionGenerator.schemeName(scheme) + ".instance.xml");
    }

    /** The number of roles (seats), the commander's included. */
    public int seats() {
        return 1 + roles.stream().mapToInt(RoleType::seats).sum();
    }

    /** The team: the commander first, then one vehicle per seat, role by role. */
    public List<SimVehicle> vehicles() {
        return vehicles(0);
    }

    /**
     * The team with spare vehicles: the commander first, then for each role one vehicle per seat and
     * {@code sparePercent} percent more (rounded up), built for that role like the others, so that the
     * role's last seats need not wait for its last free vehicle.
     *
     * @throws IllegalArgumentException when {@code sparePercent} is below 0 or above 1,000
     */
    public List<SimVehicle> vehicles(int sparePercent) {
        if (sparePercent < 0 || sparePercent > MAX_SPARE_PERCENT) {
            throw new IllegalArgumentException("spare vehicles " + sparePercent + "% must be from 0 to "
                    + MAX_SPARE_PERCENT + "%");
        }
        List<SimVehicle> team = new ArrayList<>(seats());
        team.add(new SimVehicle(COMMANDER, Set.of(MissionGenerator.RADIO), Set.of(), true, false));
        for (RoleType r : roles) {
            int built = r.seats() + (r.seats() * sparePercent + 99) / 100;
            for (int s = 0; s < built; s++) {
                team.add(new SimVehicle(r.vehicle(s), Set.of(MissionGenerator.RADIO, r.resource()), Set.of(), false, false));
            }
        }
        return team;
    }

    /** The roles a holder of {@code role} discovers and assigns under {@code scheme}. */
    public List<RoleType> managedBy(String role, Scheme scheme) {
        if (scheme == Scheme.CENTRALISED) {
            return role.equals("commander") ? roles : List.of();
        }
        return roles.stream().filter(r -> r.manager().equals(role)).toList();
    }

    /**
     * How many {@code newUAV} obligation policies the vehicle {@code vehicle} runs when it holds the
     * role it was built for (one per role it may assign): what one discovery reply costs it.
     */
    public int newUavPolicies(String vehicle, Scheme scheme) {
        String role = vehicle.equals(COMMANDER) ? "commander" : RoleType.roleOfVehicle(vehicle).orElse("");
        return managedBy(role, scheme).size();
    }

    /**
     * Whether the vehicle {@code vehicle} loads the policy {@code uri} into its engine: it does for the
     * policy files of the role it was built for; the others it receives (a manager's copies of the
     * roles below it, served to its children; a backup commander's copy of the mission's) it only keeps.
     */
    public boolean loadsPolicy(String vehicle, String uri) {
        String role = vehicle.equals(COMMANDER) ? "commander" : RoleType.roleOfVehicle(vehicle).orElse(null);
        return role != null && uri.startsWith("policy:/roles/" + role + "/");
    }

    /** Role name to role, for look-ups. */
    public Map<String, RoleType> byName() {
        Map<String, RoleType> m = new LinkedHashMap<>();
        roles.forEach(r -> m.put(r.name(), r));
        return m;
    }
}
