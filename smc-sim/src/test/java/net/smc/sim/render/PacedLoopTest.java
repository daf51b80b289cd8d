package net.smc.sim.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

import net.smc.core.transport.sim.SimulationScheduler;
import org.junit.jupiter.api.Test;

/** The pacing on a fake wall clock that the waiter advances: no sleeps, no window. */
class PacedLoopTest {
    private static final long MS = TimeUnit.MILLISECONDS.toNanos(1);
    private long wall;

    private PacedLoop loop(ViewControls controls) {
        return new PacedLoop(controls, 40, () -> wall, nanos -> wall += nanos);
    }

    @Test
    void realTime_advancesTheMissionByTheWallTime() throws InterruptedException {
        SimulationScheduler scheduler = new SimulationScheduler();
        long frames = loop(ViewControls.defaults()).run(scheduler::runFor, () -> { }, () -> wall >= 2_000 * MS);
        assertEquals(50, frames);
        assertEquals(1_960, scheduler.nowMillis(), "49 frames of 40 ms after the first");
    }

    @Test
    void speed_scalesTheMissionTimePerFrame_andPauseStopsIt() {
        ViewControls controls = ViewControls.defaults();
        PacedLoop loop = loop(controls);
        assertEquals(0, loop.advanceFor(0));
        assertEquals(40, loop.advanceFor(40 * MS));
        controls.key('+');
        controls.key('+');
        assertEquals(160, loop.advanceFor(80 * MS));
        controls.key(' ');
        assertEquals(0, loop.advanceFor(120 * MS));
        controls.key(' ');
        controls.key('-');
        controls.key('-');
        controls.key('-');
        assertEquals(20, loop.advanceFor(160 * MS));
    }

    @Test
    void fractionsOfAMillisecond_carryOver() {
        ViewControls controls = new ViewControls(0.125, Overlays.defaults());
        PacedLoop loop = loop(controls);
        loop.advanceFor(0);
        long sum = 0;
        for (int i = 1; i <= 10; i++) {
            sum += loop.advanceFor(i * 3 * MS);
        }
        assertEquals(3, sum, "30 ms at 1/8 speed: 3.75 ms, 3 whole");
    }

    @Test
    void aLongStall_isNotCaughtUp() {
        PacedLoop loop = loop(ViewControls.defaults());
        loop.advanceFor(0);
        assertEquals(TimeUnit.NANOSECONDS.toMillis(PacedLoop.MAX_CATCH_UP_NANOS), loop.advanceFor(5_000 * MS));
    }

    @Test
    void frames_waitOnlyForWhatIsLeftOfTheirPeriod() throws InterruptedException {
        List<Long> waits = new ArrayList<>();
        PacedLoop loop = new PacedLoop(ViewControls.defaults(), 40, () -> wall, nanos -> {
            waits.add(nanos / MS);
            wall += nanos;
        });
        loop.run(ms -> wall += 30 * MS, () -> { }, () -> waits.size() >= 3);
        assertEquals(List.of(40L, 10L, 10L), waits, "the first frame advances nothing; later ones take 30 of their 40 ms");
    }

    @Test
    void framePeriod_outOfRange_isRefused() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new PacedLoop(ViewControls.defaults(), 1, () -> 0, n -> { }));
        assertTrue(e.getMessage().contains("frame period 1 ms"), e.getMessage());
    }
}
