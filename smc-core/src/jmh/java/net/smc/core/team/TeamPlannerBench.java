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
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;

/**
 * Goal: {@link TeamPlanner#plan} for 1,000 vehicles and a mission of 100 roles in under 50 ms.
 * The mission is a commander over 33 primary roles, each managing two secondary roles that may
 * ride on it; every role needs one or two of 12 resources and one of 8 tasks; minimal
 * cardinalities 1 to 3, optimal up to 5 more. Fleets: {@code AMPLE} (1,000 vehicles, 3 resources
 * and 3 tasks each: the minimal configuration exists, the search's first path finds it) and
 * {@code SCARCE} (1,000 vehicles with one resource and one task each: no minimal configuration;
 * the search's counting bounds prove it at once and the greedy fallback fills what it can).
 * Setup checks, untimed, which of the two each fleet is. {@link TeamPlannerWorstCaseBench}
 * prices a search that spends its whole budget.
 */
@State(Scope.Thread)
@Fork(1)
@Warmup(iterations = 3, time = 2)
@Measurement(iterations = 5, time = 2)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
public class TeamPlannerBench {
    private static final int PRIMARIES = 33;
    private static final int RESOURCES = 12;
    private static final int TASKS = 8;

    @Param({"AMPLE", "SCARCE"})
    String fleet;

    @Param({"1000"})
    int vehicles;

    private Mission mission;
    private List<CapabilitySummary> summaries;

    @Setup
    public void setUp() {
        Random random = new Random(42);
        mission = mission(random);
        boolean ample = fleet.equals("AMPLE");
        summaries = fleet(random, vehicles, ample ? 3 : 1, ample ? 3 : 1);
        boolean met = TeamPlanner.plan(mission, summaries).minimalMet();
        if (met != ample) {
            throw new IllegalStateException(fleet + " fleet: minimal configuration " + (met ? "met" : "not met"));
        }
    }

    @Benchmark
    public TeamConfiguration plan() {
        return TeamPlanner.plan(mission, summaries);
    }

    static Mission mission(Random random) {
        List<MissionRole> roles = new ArrayList<>();
        List<String> primaries = new ArrayList<>();
        List<Colocation.Parallel> parallel = new ArrayList<>();
        for (int p = 0; p < PRIMARIES; p++) {
            String primary = "p" + p;
            primaries.add(primary);
            List<String> secondaries = List.of(primary + "s0", primary + "s1");
            roles.add(role(random, primary, secondaries, null));
            for (String secondary : secondaries) {
                roles.add(role(random, secondary, List.of(), primary));
                parallel.add(new Colocation.Parallel(secondary, List.of(primary)));
            }
            parallel.add(new Colocation.Parallel(secondaries.get(0), List.of(secondaries.get(1))));
        }
        roles.add(0, new MissionRole(Mission.COMMANDER, 1, 1, primaries, CapabilityRequirement.of(Set.of("r0"), Set.of()),
                Optional.empty(), List.of("policy:/roles/commander/mission"), List.of()));
        return new Mission("Bench", "bench", roles, new Colocation(parallel, List.of()), Map.of());
    }

    private static MissionRole role(Random random, String name, List<String> manages, String primary) {
        Set<String> resources = new TreeSet<>();
        for (int i = 0; i <= random.nextInt(2); i++) {
            resources.add("r" + random.nextInt(RESOURCES));
        }
        int minimal = 1 + random.nextInt(3);
        return new MissionRole(name, minimal, minimal + random.nextInt(6), manages,
                CapabilityRequirement.of(resources, Set.of("t" + random.nextInt(TASKS))), Optional.ofNullable(primary),
                List.of("policy:/roles/" + name + "/mission"), List.of());
    }

    static List<CapabilitySummary> fleet(Random random, int n, int resources, int tasks) {
        List<CapabilitySummary> fleet = new ArrayList<>();
        for (int v = 0; v < n; v++) {
            TreeSet<String> has = new TreeSet<>();
            TreeSet<String> runs = new TreeSet<>();
            while (has.size() < resources) {
                has.add("r" + random.nextInt(RESOURCES));
            }
            while (runs.size() < tasks) {
                runs.add("t" + random.nextInt(TASKS));
            }
            fleet.add(new CapabilitySummary(String.format("uav-%04d", v), has, runs));
        }
        return fleet;
    }
}
