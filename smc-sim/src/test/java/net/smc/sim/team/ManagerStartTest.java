package net.smc.sim.team;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

import net.smc.core.cell.CellEvent;
import net.smc.core.cell.MissionState;
import net.smc.core.cell.Missions;
import org.junit.jupiter.api.Test;

/**
 * A manager discovers its children as soon as its role starts, and a commander as soon as it
 * starts: neither waits for its next tick (up to a heartbeat period, per level of the tree).
 */
class ManagerStartTest {
    private final List<CellEvent> events = new ArrayList<>();

    private Optional<Long> first(String vehicle, CellEvent.Kind kind) {
        return events.stream().filter(e -> e.vehicle().equals(vehicle) && e.kind() == kind).map(CellEvent::timeMillis)
                .findFirst();
    }

    @Test
    void managersDiscoverTheMomentTheirRoleStarts() {
        for (long seed = 61; seed < 64; seed++) {
            events.clear();
            TeamSimulation sim = TeamSimulation.builder(Missions.reconnaissance(), Missions.REPOSITORY, seed)
                    .vehicles(SimVehicle.reconnaissance(2, 1, 2, 2)).listener(events::add).build();
            sim.start();
            assertTrue(sim.runUntil(() -> sim.cell("cdr").missionState().equals(Optional.of(MissionState.OPTIMAL)),
                    10_000), "seed " + seed + ": the team forms");
            long started = first("cdr", CellEvent.Kind.COMMANDING).orElseThrow();
            assertEquals(Optional.of(started), first("cdr", CellEvent.Kind.DISCOVERING),
                    "seed " + seed + ": the commander discovers when it starts");
            for (String surveyor : List.of("s1", "s2")) {
                long accepted = first(surveyor, CellEvent.Kind.ACCEPTED).orElseThrow();
                assertEquals(Optional.of(accepted), first(surveyor, CellEvent.Kind.DISCOVERING),
                        "seed " + seed + ": " + surveyor + " discovers for its seats when it takes its role");
            }
        }
    }
}
