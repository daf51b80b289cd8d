package net.smc.sim.team;

import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import net.smc.core.cell.Missions;
import net.smc.core.transport.Address;
import net.smc.core.transport.sim.NetworkObserver;
import org.junit.jupiter.api.Test;

/** Whole teams with real cryptography under an adversary who records, replays and forges datagrams. */
class HostileNetworkTest {
    private static final int HELLO = 2;

    private static TeamSimulation sim(long seed, List<SimVehicle> vehicles) {
        return TeamSimulation.builder(Missions.reconnaissance(), Missions.REPOSITORY, seed).vehicles(vehicles)
                .security(TeamSimulation.Security.REAL).build();
    }

    private static void until(TeamSimulation sim, java.util.function.BooleanSupplier condition, long maxMillis, String what) {
        boolean reached;
        try {
            reached = sim.runUntil(condition, maxMillis);
        } catch (InvariantViolation v) {
            throw new AssertionError(v.report(), v);
        }
        assertTrue(reached, () -> what + " not reached within " + maxMillis + " ms (" + sim.invariants().unsettled()
                + ")\n" + String.join("\n", sim.trace()));
    }

    /**
     * The commander's HELLO to s1, recorded while s1 joins, is replayed every 20 ms for 5 s from
     * another address while s1 restarts (with new keys): s1 must still get a role.
     */
    @Test
    void aReplayedHandshakeDoesNotLockARestartingVehicleOut() {
        TeamSimulation sim = sim(41, SimVehicle.reconnaissance(2, 1, 0, 0));
        Address cdr = sim.address("cdr");
        Address s1 = sim.address("s1");
        List<byte[]> hellos = new ArrayList<>();
        sim.network().addObserver(new NetworkObserver() {
            @Override
            public void delivered(long atMillis, Address from, Address to, byte[] data) {
                if (from.equals(cdr) && to.equals(s1) && data.length > 1 && data[1] == HELLO && hellos.isEmpty()) {
                    hellos.add(data.clone());
                }
            }
        });
        sim.start();
        until(sim, () -> !sim.cell("s1").seats().isEmpty(), 20_000, "s1 holding a role");
        byte[] hello = hellos.get(0);
        assertNotNull(hello);
        sim.crash("s1");
        sim.run(500);
        for (int i = 0; i < 250; i++) {
            sim.network().inject(Address.loopback(9999), s1, hello, 20L * i);
        }
        sim.restart("s1");
        until(sim, () -> !sim.cell("s1").seats().isEmpty(), 30_000, "the restarted s1 holding a role again");
        until(sim, () -> sim.invariants().settled(), 20_000, "the best configuration");
    }
}
