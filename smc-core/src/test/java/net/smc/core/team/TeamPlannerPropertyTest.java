package net.smc.core.team;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Random;
import java.util.Set;
import net.smc.core.capability.CapabilitySummary;
import net.smc.core.mission.Mission;
import net.smc.core.mission.MissionRole;
import org.junit.jupiter.api.Test;

/**
 * Random missions and fleets, many seeds each (seeded {@link Random}: a failure names its seed and
 * replays). The invariants are checked from the mission's rules ({@link Invariants}); reaching the
 * minimal configuration is checked against a search of every assignment ({@link BruteForce}).
 */
class TeamPlannerPropertyTest {
    private static final int SEEDS = 3000;

    @Test
    void randomSmallTeams_keepEveryInvariant_andMeetMinimalExactlyWhenSomeAssignmentCan() {
        int met = 0;
        for (int seed = 0; seed < SEEDS; seed++) {
            Random random = new Random(seed);
            Mission mission = Fixtures.randomMission(random, 4);
            List<CapabilitySummary> vehicles = Fixtures.randomVehicles(random, random.nextInt(7));

            TeamConfiguration team = TeamPlanner.plan(mission, vehicles);

            Invariants.check(mission, vehicles, team, "seed " + seed);
            assertEquals(BruteForce.minimalPossible(mission, vehicles), team.minimalMet(), "seed " + seed);
            met += team.minimalMet() ? 1 : 0;
        }
        assertTrue(met > SEEDS / 10 && met < SEEDS * 9 / 10, "the random cases mix feasible and infeasible: " + met);
    }

    @Test
    void randomLargerTeams_keepEveryInvariant() {
        for (int seed = 0; seed < 300; seed++) {
            Random random = new Random(seed);
            Mission mission = Fixtures.randomMission(random, 8);
            List<CapabilitySummary> vehicles = Fixtures.randomVehicles(random, random.nextInt(60));

            Invariants.check(mission, vehicles, TeamPlanner.plan(mission, vehicles), "seed " + seed);
        }
    }

    @Test
    void sameVehiclesInAnyOrder_giveTheSameConfiguration() {
        for (int seed = 0; seed < 500; seed++) {
            Random random = new Random(seed);
            Mission mission = Fixtures.randomMission(random, 5);
            List<CapabilitySummary> vehicles = new ArrayList<>(Fixtures.randomVehicles(random, random.nextInt(12)));
            TeamConfiguration first = TeamPlanner.plan(mission, vehicles);

            Collections.shuffle(vehicles, random);

            assertEquals(first, TeamPlanner.plan(mission, vehicles), "seed " + seed);
        }
    }

    @Test
    void addingAVehicle_neverLosesTheMinimalConfiguration() {
        for (int seed = 0; seed < SEEDS; seed++) {
            Random random = new Random(seed);
            Mission mission = Fixtures.randomMission(random, 4);
            List<CapabilitySummary> vehicles = new ArrayList<>(Fixtures.randomVehicles(random, 1 + random.nextInt(8)));
            CapabilitySummary joining = vehicles.remove(random.nextInt(vehicles.size()));
            TeamConfiguration before = TeamPlanner.plan(mission, vehicles);

            vehicles.add(joining);
            TeamConfiguration after = TeamPlanner.plan(mission, vehicles);

            assertTrue(!before.minimalMet() || after.minimalMet(), "seed " + seed + ": " + joining + " joined and broke " + after);
        }
    }

    @Test
    void vehicleFitForOneSecondaryRole_takesItOverWhenItJoins_andGivesItBackWhenItLeaves() {
        int moved = 0;
        for (int seed = 0; seed < SEEDS; seed++) {
            Random random = new Random(seed);
            Mission mission = Fixtures.randomMission(random, 4);
            List<CapabilitySummary> vehicles = new ArrayList<>(Fixtures.randomVehicles(random, random.nextInt(8)));
            TeamConfiguration before = TeamPlanner.plan(mission, vehicles);
            MissionRole carried = carriedAtOptimal(mission, before);
            if (carried == null) {
                continue;
            }
            CapabilitySummary dedicated = Fixtures.vehicle("zz-new", carried.requirement().resources(),
                    carried.requirement().tasks());
            if (fitsOtherRoles(mission, carried, dedicated)) {
                continue;
            }
            vehicles.add(dedicated);

            TeamConfiguration after = TeamPlanner.plan(mission, vehicles);

            assertEquals(List.of(carried.name()), after.rolesOf("zz-new"), "seed " + seed + ": the new vehicle takes the role");
            // It relieves a carrier, unless the vehicle that held the role before is now free to
            // grow another role that was below optimal (primary roles get vehicles first).
            assertTrue(carriers(after, carried.name()) == carriers(before, carried.name()) - 1
                    || anotherRoleGrew(mission, carried, before, after), "seed " + seed
                    + ": one vehicle no longer carries " + carried.name() + ", or another role grew");
            vehicles.remove(dedicated);
            assertEquals(before, TeamPlanner.plan(mission, vehicles), "seed " + seed + ": it returns when the vehicle leaves");
            moved++;
        }
        assertTrue(moved > 50, "cases where a carried secondary role could move: " + moved);
    }

    /** A secondary role at its optimal count that some vehicle carries beside its primary. */
    private static MissionRole carriedAtOptimal(Mission mission, TeamConfiguration team) {
        for (MissionRole role : mission.roles()) {
            if (role.isSecondary() && team.holdersOf(role.name()).size() == role.optimal() && carriers(team, role.name()) > 0) {
                return role;
            }
        }
        return null;
    }

    private static long carriers(TeamConfiguration team, String role) {
        return team.assignments().stream().filter(a -> a.roles().contains(role) && !a.anchor().equals(role)).count();
    }

    private static boolean anotherRoleGrew(Mission mission, MissionRole moved, TeamConfiguration before,
                                           TeamConfiguration after) {
        return mission.roles().stream().anyMatch(r -> r != moved && before.holdersOf(r.name()).size() < r.optimal()
                && after.holdersOf(r.name()).size() > before.holdersOf(r.name()).size());
    }

    private static boolean fitsOtherRoles(Mission mission, MissionRole role, CapabilitySummary vehicle) {
        return mission.roles().stream().anyMatch(r -> r != role && r.requirement().isMetBy(vehicle));
    }

    @Test
    void planningTwice_isPure() {
        Random random = new Random(7);
        Mission mission = Fixtures.randomMission(random, 6);
        List<CapabilitySummary> vehicles = Fixtures.randomVehicles(random, 30);
        List<CapabilitySummary> copy = List.copyOf(vehicles);

        TeamConfiguration first = TeamPlanner.plan(mission, vehicles);

        assertEquals(first, TeamPlanner.plan(mission, vehicles));
        assertEquals(copy, vehicles, "the input is not changed");
        assertEquals(Set.copyOf(first.spare()).size(), first.spare().size());
    }
}
