package net.smc.sim.team;

import java.util.stream.LongStream;
import java.util.stream.Stream;

import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.TestFactory;

import net.smc.core.cell.Missions;

/**
 * The invariant checks keep their readings of the cells from check to check, re-reading a cell only
 * when its link version moved: seeded fault schedules (crashes, restarts, partitions, loss, joins,
 * leaves, an adversary on some seeds) with every check also reading every cell in full, which fails
 * the run if any incremental reading is stale, i.e. if some writer of a cell's parent, command,
 * lease, seats or children did not move the version. {@code smc.readings.seeds} seeds from 1 (150).
 */
class InvariantReadingsSweepTest {
    private static final long SEEDS = Long.getLong("smc.readings.seeds", 150);

    @TestFactory
    Stream<DynamicTest> incrementalReadingsMatchAFullReadAtEveryCheck() {
        return LongStream.rangeClosed(1, SEEDS).mapToObj(seed -> DynamicTest.dynamicTest("seed " + seed, () -> {
            try {
                new FaultSchedule(Missions.reconnaissance(), Missions.centralised(), Missions.REPOSITORY, seed, 30_000)
                        .verifyInvariantReadings(true).run();
            } catch (InvariantViolation v) {
                throw new AssertionError(v.report(), v);
            }
        }));
    }
}
