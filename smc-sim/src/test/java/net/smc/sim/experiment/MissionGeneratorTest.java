package net.smc.sim.experiment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

import net.smc.core.cell.Scheme;
import net.smc.core.cell.Slots;
import net.smc.core.mission.Mission;
import net.smc.core.mission.MissionLoader;
import net.smc.policy.api.PolicyRepository;
import net.smc.sim.team.SimVehicle;

class MissionGeneratorTest {
    @TempDir
    Path dir;

    /** A heartbeat period given replaces the default, with the failure timeout six of it, in both schemes. */
    @Test
    void comTimeout_isTheMissionsHeartbeatPeriod_andTheFailureTimeoutSixOfIt() throws Exception {
        GeneratedMission g = MissionGenerator.write(TreeShape.of(10, 4), dir, Project.bootEvents(), 750);
        MissionLoader loader = new MissionLoader(new PolicyRepository(g.repository()));
        for (Scheme scheme : Scheme.values()) {
            net.smc.core.cell.Timing timing = net.smc.core.cell.Timing.of(loader.load(g.instanceFile(scheme)));
            assertEquals(750, timing.comTimeoutMillis());
            assertEquals(4_500, timing.failureTimeoutMillis());
        }
        GeneratedMission byDefault = MissionGenerator.write(TreeShape.of(10, 4), dir.resolve("d"), Project.bootEvents());
        assertEquals(MissionGenerator.COM_TIMEOUT_MILLIS, net.smc.core.cell.Timing.of(new MissionLoader(
                new PolicyRepository(byDefault.repository())).load(byDefault.instanceFile(Scheme.DISTRIBUTED))).comTimeoutMillis());
        IllegalArgumentException zero = assertThrows(IllegalArgumentException.class,
                () -> MissionGenerator.write(TreeShape.of(10, 4), dir.resolve("z"), Project.bootEvents(), 0));
        assertTrue(zero.getMessage().contains("comTimeout 0 ms must be from 1 to 60000"), zero.getMessage());
    }

    @ParameterizedTest(name = "{0} roles, depth {1}")
    @CsvSource({"5, 4", "20, 4", "100, 4", "1000, 4", "2000, 4", "7, 2", "50, 3", "300, 6"})
    void generatedMission_loadsInBothSchemes_withOneSeatPerRole(int roles, int depth) throws Exception {
        GeneratedMission g = MissionGenerator.write(TreeShape.of(roles, depth), dir, Project.bootEvents());
        assertEquals(roles, g.seats());
        assertEquals(roles, g.vehicles().size());
        MissionLoader loader = new MissionLoader(new PolicyRepository(g.repository()));
        for (Scheme scheme : Scheme.values()) {
            Mission mission = loader.load(g.instanceFile(scheme));
            Slots slots = new Slots(mission, scheme);
            assertEquals(roles, slots.all().size());
            int deepest = slots.roles().stream().mapToInt(slots::level).max().orElseThrow();
            assertEquals(scheme == Scheme.CENTRALISED ? 1 : depth - 1, deepest);
        }
    }

    @Test
    void levels_areFullFromTheTop_andManagersHaveAtMostTheFanOut() throws Exception {
        TreeShape shape = TreeShape.of(1000, 4);
        assertEquals(10, shape.fanOut());
        assertEquals(List.of(1, 10, 100, 889), shape.levelSizes());
        GeneratedMission g = MissionGenerator.write(shape, dir, Project.bootEvents());
        Mission mission = new MissionLoader(new PolicyRepository(g.repository())).load(g.instanceFile(Scheme.DISTRIBUTED));
        Slots slots = new Slots(mission, Scheme.DISTRIBUTED);
        int most = slots.all().stream().mapToInt(s -> slots.ownedBy(s).size()).max().orElseThrow();
        assertTrue(most <= 10, "a manager owns " + most + " seats");
    }

    /** Spares: a tenth more of each role, rounded up (a role of one seat gets one), each built for its role alone. */
    @Test
    void spareVehicles_aPercentMoreOfEachRole_roundedUp_eachFittingItsOwnRole() throws Exception {
        GeneratedMission g = MissionGenerator.write(TreeShape.of(1000, 4), dir, Project.bootEvents());
        Mission mission = new MissionLoader(new PolicyRepository(g.repository())).load(g.instanceFile(Scheme.DISTRIBUTED));
        List<SimVehicle> team = g.vehicles(10);
        assertEquals(team.size(), team.stream().map(SimVehicle::id).distinct().count(), "ids are distinct");
        for (RoleType r : g.roles()) {
            long fit = team.stream().filter(v -> mission.role(r.name()).orElseThrow().requirement().isMetBy(v.description()))
                    .count();
            assertEquals(r.seats() + (long) Math.ceil(r.seats() / 10.0), fit, r.name() + " of " + r.seats() + " seats");
        }
        assertEquals(g.vehicles(), g.vehicles(0));
        assertEquals(1 + 10 * (1 + 1) + 10 * (10 + 1) + 889 + 10 * 9, g.vehicles(10).size(), "roles of 1, 10 and 88 or 89 seats");
        assertThrows(IllegalArgumentException.class, () -> g.vehicles(-1));
        assertThrows(IllegalArgumentException.class, () -> g.vehicles(GeneratedMission.MAX_SPARE_PERCENT + 1));
    }

    @Test
    void eachVehicle_fitsExactlyItsOwnRole() throws Exception {
        GeneratedMission g = MissionGenerator.write(TreeShape.of(20, 4), dir, Project.bootEvents());
        Mission mission = new MissionLoader(new PolicyRepository(g.repository())).load(g.instanceFile(Scheme.DISTRIBUTED));
        for (var v : g.vehicles()) {
            long fits = g.roles().stream()
                    .filter(r -> mission.role(r.name()).orElseThrow().requirement().isMetBy(v.description())).count();
            assertEquals(v.commander() ? 0 : 1, fits, v.id());
        }
    }

    @Test
    void badShapes_areRefusedWithTheRule() {
        IllegalArgumentException few = assertThrows(IllegalArgumentException.class, () -> TreeShape.of(3, 4));
        assertTrue(few.getMessage().contains("cannot fill a tree of depth 4"), few.getMessage());
        IllegalArgumentException small = assertThrows(IllegalArgumentException.class, () -> new TreeShape(100, 4, 2));
        assertTrue(small.getMessage().contains("holds at most 15 roles"), small.getMessage());
        IllegalArgumentException shallow = assertThrows(IllegalArgumentException.class, () -> TreeShape.of(10, 1));
        assertTrue(shallow.getMessage().contains("depth 1 is too small"), shallow.getMessage());
    }
}
