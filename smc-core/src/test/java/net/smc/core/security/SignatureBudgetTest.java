package net.smc.core.security;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import net.smc.core.transport.Address;
import org.junit.jupiter.api.Test;

class SignatureBudgetTest {
    private final Address a = Address.loopback(1);
    private final Address b = Address.loopback(2);

    private static int takes(SignatureBudget budget, Address from, long now, int tries) {
        int n = 0;
        for (int i = 0; i < tries; i++) {
            if (budget.take(from, now)) {
                n++;
            }
        }
        return n;
    }

    @Test
    void oneSourceSpendsItsOwnBudget_andOthersKeepTheirs() {
        SignatureBudget budget = new SignatureBudget(5, 20);
        assertEquals(5, takes(budget, a, 0, 100));
        assertEquals(5, takes(budget, b, 0, 100));
    }

    @Test
    void theTotalBoundsAllSources() {
        SignatureBudget budget = new SignatureBudget(5, 12);
        int n = 0;
        for (int port = 1; port <= 10; port++) {
            n += takes(budget, Address.loopback(port), 0, 100);
        }
        assertEquals(12, n);
    }

    @Test
    void theBudgetRefillsWithTime_upToItsRate() {
        SignatureBudget budget = new SignatureBudget(10, 100);
        assertEquals(10, takes(budget, a, 0, 100));
        assertFalse(budget.take(a, 50));
        assertTrue(budget.take(a, 100), "one a tenth of a second later");
        assertEquals(10, takes(budget, a, 60_000, 100), "an idle minute refills to the rate, not beyond");
    }
}
