package net.smc.core.team;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Random;
import java.util.Set;
import java.util.TreeSet;
import java.util.concurrent.TimeUnit;
import net.smc.core.capability.CapabilityRequirement;
import net.smc.core.capability.CapabilitySummary;
import net.smc.core.mission.Colocation;
import net.smc.core.mission.Mission;
import net.smc.core.mission.MissionRole;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;

/**
 * The price of the minimal search's budget ({@link MinimalSearch#BUDGET}): a mission whose
 * minimal configuration is a set cover with no solution that the counting bounds cannot see. A
 * primary role needs 5 vehicles; each of its 6 secondary roles needs 5 holders, riding on those
 * vehicles or on their own; 14 vehicles can each hold the primary and a random half of the
 * secondary roles. Every role alone has enough candidates, so the search tries its whole budget
 * before the greedy fallback runs. Setup checks,
 * untimed, that the minimal configuration is indeed not met.
 */
@State(Scope.Thread)
@Fork(1)
@Warmup(iterations = 3, time = 2)
@Measurement(iterations = 5, time = 2)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
public class TeamPlannerWorstCaseBench {
    private Mission mission;
    private List<CapabilitySummary> fleet;

    @Setup
    public void setUp() {
        List<String> secondaries = List.of("s0", "s1", "s2", "s3", "s4", "s5");
        List<MissionRole> roles = new ArrayList<>();
        roles.add(role("commander", 1, List.of("p"), Set.of(), null));
        roles.add(role("p", 5, secondaries, Set.of("p"), null));
        List<Colocation.Parallel> parallel = new ArrayList<>();
        for (String secondary : secondaries) {
            roles.add(role(secondary, 5, List.of(), Set.of(secondary), "p"));
            List<String> with = new ArrayList<>(List.of("p"));
            secondaries.stream().filter(other -> !other.equals(secondary)).forEach(with::add);
            parallel.add(new Colocation.Parallel(secondary, with));
        }
        mission = new Mission("WorstCase", "bench", roles, new Colocation(parallel, List.of()), Map.of());
        // Each vehicle can hold the primary and a random half of the secondary roles (seed 0:
        // no minimal configuration, which the counting bounds do not see).
        Random random = new Random(0);
        fleet = new ArrayList<>(List.of(new CapabilitySummary("cmd", new TreeSet<>(), new TreeSet<>())));
        for (int v = 0; v < 14; v++) {
            TreeSet<String> resources = new TreeSet<>(Set.of("p"));
            for (String secondary : secondaries) {
                if (random.nextInt(2) == 0) {
                    resources.add(secondary);
                }
            }
            fleet.add(new CapabilitySummary("v" + v, resources, new TreeSet<>()));
        }
        if (TeamPlanner.plan(mission, fleet).minimalMet()) {
            throw new IllegalStateException("the worst case has a minimal configuration after all");
        }
    }

    private static MissionRole role(String name, int count, List<String> manages, Set<String> resources, String primary) {
        return new MissionRole(name, count, count, manages, CapabilityRequirement.of(resources, Set.of()),
                Optional.ofNullable(primary), List.of("policy:/roles/" + name + "/mission"), List.of());
    }

    @Benchmark
    public TeamConfiguration exhaustBudget() {
        return TeamPlanner.plan(mission, fleet);
    }
}
