package net.smc.core.mission;

import java.util.List;
import java.util.Objects;
import java.util.stream.Stream;

/**
 * Which roles may share one vehicle (the paper's section II-A). By default a vehicle holds one role.
 * A {@link Parallel} rule lets roles run at the same time on one vehicle (the relay beside a
 * surveyor); an {@link Exclusive} rule lets roles share a vehicle that switches between them, one
 * active at a time (surveyor and hazard detector). Which roles ride on which is decided by
 * {@link MissionRole#primary()}; see {@link Mission#allowsOnOneVehicle}.
 *
 * @param parallel  the parallel rules, in the class file's order
 * @param exclusive the exclusive rules, in the class file's order
 */
public record Colocation(List<Parallel> parallel, List<Exclusive> exclusive) {
    private static final Colocation NONE = new Colocation(List.of(), List.of());

    public Colocation {
        parallel = List.copyOf(parallel);
        exclusive = List.copyOf(exclusive);
    }

    /** No rules: every vehicle holds one role. */
    public static Colocation none() {
        return NONE;
    }

    /** Whether some rule lets roles {@code a} and {@code b} (two different roles) share a vehicle. */
    public boolean mayShare(String a, String b) {
        return !a.equals(b) && (runInParallel(a, b) || switchBetween(a, b));
    }

    /** Whether {@code a} and {@code b} may run at the same time on one vehicle. */
    public boolean runInParallel(String a, String b) {
        return parallel.stream().anyMatch(p -> p.pairs(a, b));
    }

    /** Whether a vehicle holding {@code a} and {@code b} switches between them. */
    public boolean switchBetween(String a, String b) {
        return exclusive.stream().anyMatch(e -> e.roles.contains(a) && e.roles.contains(b) && !a.equals(b));
    }

    /** Every role some rule names, in rule order, with repeats. */
    Stream<String> namedRoles() {
        return Stream.concat(parallel.stream().flatMap(p -> Stream.concat(Stream.of(p.role), p.with.stream())),
                exclusive.stream().flatMap(e -> e.roles.stream()));
    }

    /**
     * {@code <parallel role="relay" with="surveyor hdetector"/>}: {@code role} may run at the same
     * time as any one of {@code with} on one vehicle.
     */
    public record Parallel(String role, List<String> with) {
        public Parallel {
            Objects.requireNonNull(role, "role");
            with = List.copyOf(with);
        }

        boolean pairs(String a, String b) {
            return role.equals(a) && with.contains(b) || role.equals(b) && with.contains(a);
        }
    }

    /**
     * {@code <exclusive roles="surveyor hdetector"/>}: any of {@code roles} may share a vehicle,
     * which runs one of them at a time.
     */
    public record Exclusive(List<String> roles) {
        public Exclusive {
            roles = List.copyOf(roles);
        }
    }
}
