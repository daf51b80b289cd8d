package net.smc.core.transport.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

class LinkProfileTest {

    @Test
    void default_isOneMillisecondWithoutFaults() {
        assertEquals(new LinkProfile(1, 0, 0, 0, 0, 0), LinkProfile.DEFAULT);
    }

    @Test
    void withers_changeOneThingEach() {
        LinkProfile p = LinkProfile.fixed(5).withLatency(7, 3).withLoss(0.1).withDuplication(0.2).withReorder(0.3, 40);
        assertEquals(new LinkProfile(7, 3, 0.1, 0.2, 0.3, 40), p);
    }

    @Test
    void negativeLatency_isRefused() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> LinkProfile.fixed(-1));
        assertEquals("latency of -1 ms is negative; it must be 0 or more", e.getMessage());
    }

    @Test
    void negativeJitter_isRefused() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> LinkProfile.DEFAULT.withLatency(1, -2));
        assertEquals("jitter of -2 ms is negative; it must be 0 or more", e.getMessage());
    }

    @Test
    void probabilityOutsideZeroToOne_isRefused() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> LinkProfile.DEFAULT.withLoss(1.5));
        assertEquals("loss probability 1.5 is not a probability; it must be from 0 to 1", e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> LinkProfile.DEFAULT.withDuplication(-0.1));
        assertThrows(IllegalArgumentException.class, () -> LinkProfile.DEFAULT.withLoss(Double.NaN));
    }

    @Test
    void reorderingWithoutAHoldBack_isRefused() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> LinkProfile.DEFAULT.withReorder(0.5, 0));
        assertEquals("reorder delay of 0 ms with reorder probability 0.5; it must be 1 ms or more when re-ordering "
                + "can happen, and never negative", e.getMessage());
    }
}
