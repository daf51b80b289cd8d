package net.smc.core.comm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class DuplicateWindowTest {

    @Test
    void firstSeen_isTrueOnce_perSenderAndId() {
        DuplicateWindow w = new DuplicateWindow(1_000, 100);
        assertTrue(w.firstSeen("a", 1, 0));
        assertFalse(w.firstSeen("a", 1, 10));
        assertTrue(w.firstSeen("b", 1, 10), "the same id from another sender is another message");
        assertTrue(w.firstSeen("a", 2, 10));
    }

    @Test
    void entries_expireAfterTheWindow() {
        DuplicateWindow w = new DuplicateWindow(1_000, 100);
        w.firstSeen("a", 1, 0);
        assertFalse(w.firstSeen("a", 1, 999));
        assertTrue(w.firstSeen("a", 1, 1_000));
        assertEquals(1, w.expired());
    }

    @Test
    void entries_areCappedOldestFirst_andEarlyEvictionsCounted() {
        DuplicateWindow w = new DuplicateWindow(1_000, 2);
        w.firstSeen("a", 1, 0);
        w.firstSeen("a", 2, 0);
        w.firstSeen("a", 3, 0);
        assertEquals(2, w.size());
        assertEquals(1, w.evictedEarly());
        assertFalse(w.firstSeen("a", 3, 1));
        assertTrue(w.firstSeen("a", 1, 1), "the evicted entry is forgotten");
    }
}
