package net.smc.core.cell;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class TimingTest {
    private final Timing timing = new Timing(500, 3_000, 1);

    @Test
    void aManagerTakesOnlyItsOwnShareForAHundredthOfAPeriodPerSibling() {
        assertEquals(0, timing.ownShareMillis(1));
        assertEquals(10, timing.ownShareMillis(2));
        assertEquals(50, timing.ownShareMillis(10));
        assertEquals(timing.senderSettings().initialTimeoutMillis(), timing.ownShareMillis(40),
                "never longer than the first retransmission timeout: a short share waits no longer than a lost reply");
    }

    @Test
    void aManagerWithoutEvenItselfIsAnError() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> timing.ownShareMillis(0));
        assertTrue(e.getMessage().contains("siblings is 0"), e.getMessage());
    }
}
