package net.smc.core.transport.real;

import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class SystemClockTest {

    @Test
    void startsAtTheWallClock() {
        long before = System.currentTimeMillis();
        long now = new SystemClock().nowMillis();
        long after = System.currentTimeMillis();
        assertTrue(now >= before && now <= after, before + " <= " + now + " <= " + after);
    }

    @Test
    void neverGoesBack() {
        SystemClock clock = new SystemClock();
        long previous = clock.nowMillis();
        for (int i = 0; i < 100_000; i++) {
            long now = clock.nowMillis();
            assertTrue(now >= previous, now + " after " + previous);
            previous = now;
        }
    }
}
