package net.smc.core.comm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;

import org.junit.jupiter.api.Test;

class BackoffTest {

    @Test
    void timeout_growsByTheFactorUpToTheCap_withoutJitter() {
        Backoff b = new Backoff(new SenderSettings(100, 2, 500, 6, 0, 10_000, 10), new SplittableRandom(1));
        long[] got = new long[6];
        for (int t = 1; t <= 6; t++) {
            got[t - 1] = b.timeoutMillis(t);
        }
        assertEquals("[100, 200, 400, 500, 500, 500]", java.util.Arrays.toString(got));
    }

    @Test
    void timeout_staysWithinTheJitterBand() {
        SenderSettings s = new SenderSettings(100, 2, 1_000, 5, 0.25, 10_000, 10);
        Backoff b = new Backoff(s, new SplittableRandom(7));
        for (int i = 0; i < 10_000; i++) {
            int tries = 1 + i % 5;
            long t = b.timeoutMillis(tries);
            double base = s.baseTimeoutMillis(tries);
            assertTrue(t >= Math.floor(base * 0.75) && t <= s.longestTimeoutMillis(tries), "try " + tries + ": " + t);
        }
    }

    @Test
    void timeout_isSpreadByJitter_andTheSameForTheSameSeed() {
        SenderSettings s = new SenderSettings(1_000, 2, 1_000, 5, 0.2, 10_000, 10);
        Backoff one = new Backoff(s, new SplittableRandom(3));
        Backoff same = new Backoff(s, new SplittableRandom(3));
        Backoff other = new Backoff(s, new SplittableRandom(4));
        StringBuilder a = new StringBuilder();
        StringBuilder b = new StringBuilder();
        StringBuilder c = new StringBuilder();
        for (int i = 0; i < 20; i++) {
            a.append(one.timeoutMillis(1)).append(' ');
            b.append(same.timeoutMillis(1)).append(' ');
            c.append(other.timeoutMillis(1)).append(' ');
        }
        assertEquals(a.toString(), b.toString());
        assertNotEquals(a.toString(), c.toString());
    }
}
