package net.smc.sim.experiment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

import net.smc.core.cell.Scheme;
import net.smc.core.mission.Mission;
import net.smc.core.mission.MissionLoader;
import net.smc.policy.api.PolicyRepository;

class UdpSetupTimeRunTest {
    @TempDir
    Path dir;

    /** A 5-role team sets up over loopback UDP with signed traffic; the wall-clock limit is a generous liveness bound. */
    @ParameterizedTest
    @EnumSource(Scheme.class)
    void fiveRoles_setUpOverLoopback(Scheme scheme) throws Exception {
        GeneratedMission g = MissionGenerator.write(TreeShape.of(5, 4), dir, Project.bootEvents());
        Mission mission = new MissionLoader(new PolicyRepository(g.repository())).load(g.instanceFile(scheme));

        SetupResult r = UdpSetupTimeRun.run(g, mission, scheme, 1, 7, 30_000);

        assertTrue(r.complete(), () -> "not every role started: " + r);
        assertEquals("udp", r.transport());
        assertEquals(4, r.started(), r::toString);
        assertTrue(r.setupMillis() > 0 && r.setupMillis() < 30_000 && r.busiestCpuMillis() > 0, r::toString);
        assertTrue(r.messages() >= 8 && r.bytes() > r.messages() * 64, () -> "signed datagrams went out: " + r);
    }

    @Test
    void moreThanFiftyRoles_areRefused() throws Exception {
        GeneratedMission g = MissionGenerator.write(TreeShape.of(51, 4), dir, Project.bootEvents());
        Mission mission = new MissionLoader(new PolicyRepository(g.repository())).load(g.instanceFile(Scheme.DISTRIBUTED));

        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> UdpSetupTimeRun.run(g, mission, Scheme.DISTRIBUTED, 1, 7, 30_000));
        assertTrue(e.getMessage().contains("at most 50 roles") && e.getMessage().contains("has 51"), e.getMessage());
    }
}
