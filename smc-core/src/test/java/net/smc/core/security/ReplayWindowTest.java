package net.smc.core.security;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class ReplayWindowTest {

    private static void accept(ReplayWindow w, long counter) {
        assertTrue(w.isFresh(counter), "counter " + counter + " should be fresh in " + w);
        w.mark(counter, 0);
    }

    @Test
    void aCounterSeenOnce_isNotFreshAgain() {
        ReplayWindow w = new ReplayWindow(4);
        accept(w, 10);

        assertFalse(w.isFresh(10));
    }

    @Test
    void reorderedCounters_passOnce() {
        ReplayWindow w = new ReplayWindow(4);
        accept(w, 30);
        accept(w, 10);
        accept(w, 20);

        assertFalse(w.isFresh(10));
        assertFalse(w.isFresh(20));
        assertTrue(w.isFresh(15));
    }

    @Test
    void sparseCounters_areRemembered() {
        ReplayWindow w = new ReplayWindow(4);
        accept(w, 5L << 20);
        accept(w, 9L << 20);

        assertFalse(w.isFresh(5L << 20));
        assertTrue(w.isFresh((5L << 20) + 1));
    }

    @Test
    void whenFull_theOldestIsForgotten_andEverythingAtOrBelowItIsRefused() {
        ReplayWindow w = new ReplayWindow(3);
        accept(w, 1);
        accept(w, 5);
        accept(w, 7);
        accept(w, 9);   // forgets 1

        assertFalse(w.isFresh(1), "forgotten, so refused");
        assertFalse(w.isFresh(0), "below the floor");
        assertTrue(w.isFresh(3), "above the floor and never seen");
        assertFalse(w.isFresh(5));
    }

    @Test
    void whenFull_aCounterOlderThanAllKept_raisesTheFloorToItself() {
        ReplayWindow w = new ReplayWindow(2);
        accept(w, 1);
        accept(w, 10);
        accept(w, 20);   // forgets 1: floor 1
        accept(w, 5);    // older than 10 and 20: remembered as the floor

        assertFalse(w.isFresh(5));
        assertFalse(w.isFresh(4));
        assertTrue(w.isFresh(15));
        assertFalse(w.isFresh(10));
    }

    /**
     * Mostly rising counters with some reordered, repeated or old ones: the window answers as a plain
     * model does (the newest 64 accepted kept in a sorted set, a floor at the newest forgotten).
     */
    @Test
    void answersAsASortedSetOfTheNewestWithAFloor() {
        ReplayWindow w = new ReplayWindow(64);
        java.util.TreeSet<Long> kept = new java.util.TreeSet<>();
        long floor = Long.MIN_VALUE;
        java.util.SplittableRandom random = new java.util.SplittableRandom(3);
        long next = 1_000;
        for (int i = 0; i < 20_000; i++) {
            long c = random.nextInt(4) == 0 ? next - random.nextInt(100) : (next += 1 + random.nextInt(3));
            boolean fresh = c > floor && !kept.contains(c);
            org.junit.jupiter.api.Assertions.assertEquals(fresh, w.isFresh(c), "counter " + c + " at step " + i);
            if (fresh) {
                w.mark(c, 0);
                if (kept.size() == 64 && c < kept.first()) {
                    floor = c;
                } else {
                    kept.add(c);
                    if (kept.size() > 64) {
                        floor = kept.pollFirst();
                    }
                }
            }
        }
    }
}
