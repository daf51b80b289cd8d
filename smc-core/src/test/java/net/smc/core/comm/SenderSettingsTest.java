package net.smc.core.comm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class SenderSettingsTest {

    @Test
    void defaults_giveUpWithinThirteenPointTwoSeconds() {
        // 200 + 400 + 800 + 1600 + 4 x 2000 ms = 11,000 ms, each stretched by up to 20% jitter.
        assertEquals(13_200, SenderSettings.DEFAULTS.failureBoundMillis());
    }

    @Test
    void failureBound_sumsEveryTrysLongestTimeout() {
        SenderSettings s = new SenderSettings(10, 3.0, 100, 4, 0.0, 1_000, 10);
        assertEquals(10 + 30 + 90 + 100, s.failureBoundMillis());
    }

    @Test
    void initialTimeout_mustBePositive() {
        var e = assertThrows(IllegalArgumentException.class, () -> new SenderSettings(0, 2, 100, 3, 0, 1_000, 10));
        assertEquals("initial timeout of 0 ms is too short; it must be 1 ms or more", e.getMessage());
    }

    @Test
    void backoffFactor_mustNotShrinkTheTimeout() {
        var e = assertThrows(IllegalArgumentException.class, () -> new SenderSettings(10, 0.5, 100, 3, 0, 1_000, 10));
        assertTrue(e.getMessage().startsWith("backoff factor 0.5 would not grow the timeout"), e.getMessage());
    }

    @Test
    void maxTimeout_mustNotBeBelowTheInitialTimeout() {
        var e = assertThrows(IllegalArgumentException.class, () -> new SenderSettings(100, 2, 50, 3, 0, 1_000, 10));
        assertEquals("max timeout of 50 ms is below the initial timeout of 100 ms; it must be at least that",
                e.getMessage());
    }

    @Test
    void maxTries_mustBeOneToAThousand() {
        var e = assertThrows(IllegalArgumentException.class, () -> new SenderSettings(10, 2, 100, 0, 0, 1_000, 10));
        assertEquals("max tries 0 is out of range; it must be 1 to 1000", e.getMessage());
    }

    @Test
    void jitter_mustBeAtMostHalf() {
        var e = assertThrows(IllegalArgumentException.class, () -> new SenderSettings(10, 2, 100, 3, 0.7, 1_000, 10));
        assertEquals("jitter fraction 0.7 is out of range; it must be from 0 to 0.5", e.getMessage());
    }

    @Test
    void duplicateWindow_mustOutlastTheRetransmissions() {
        var e = assertThrows(IllegalArgumentException.class, () -> new SenderSettings(10, 2, 100, 3, 0, 60, 10));
        assertTrue(e.getMessage().startsWith("duplicate window of 60 ms is shorter than the 70 ms over which"),
                e.getMessage());
    }

    @Test
    void duplicateWindow_mustHoldAnEntry() {
        var e = assertThrows(IllegalArgumentException.class, () -> new SenderSettings(10, 2, 100, 3, 0, 1_000, 0));
        assertEquals("duplicate window of 0 entries is too small; it must be 1 or more", e.getMessage());
    }

    @Test
    void withRetransmission_growsTheDuplicateWindowToCoverTheNewBound() {
        SenderSettings s = SenderSettings.DEFAULTS.withRetransmission(1_000, 2, 60_000, 8);
        assertTrue(s.duplicateWindowMillis() >= s.failureBoundMillis());
    }

    @Test
    void minTimeout_mustLieBetweenOneAndTheInitialTimeout() {
        var e = assertThrows(IllegalArgumentException.class, () -> new SenderSettings(10, 2, 100, 3, 0, 1_000, 10, 11));
        assertEquals("min timeout of 11 ms is out of range; it must be from 1 ms to the initial timeout of 10 ms",
                e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> new SenderSettings(10, 2, 100, 3, 0, 1_000, 10, 0));
    }

    @Test
    void adaptive_onlyWhenTheMinimumIsBelowTheInitialTimeout() {
        assertFalse(SenderSettings.DEFAULTS.adaptive());
        assertEquals(200, SenderSettings.DEFAULTS.minTimeoutMillis());
        assertTrue(SenderSettings.DEFAULTS.withAdaptiveTimeout(20).adaptive());
        assertEquals(10, SenderSettings.DEFAULTS.withAdaptiveTimeout(20).withRetransmission(10, 2, 100, 3).minTimeoutMillis(),
                "a shorter initial timeout pulls the minimum down with it");
        SenderSettings fixed = SenderSettings.DEFAULTS.withRetransmission(1_000, 2, 60_000, 8);
        assertFalse(fixed.adaptive(), "fixed settings stay fixed with a longer initial timeout");
        assertEquals(1_000, fixed.minTimeoutMillis());
    }

    @Test
    void fixedSchedule_sumsEveryTrysBaseTimeout_withinTheBound() {
        SenderSettings s = new SenderSettings(100, 2.0, 400, 4, 0.25, 10_000, 10);
        assertEquals(100 + 200 + 400 + 400, s.fixedScheduleMillis());
        assertEquals(125 + 250 + 500 + 500, s.failureBoundMillis());
    }
}
