package net.smc.core.message;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import org.junit.jupiter.api.Test;

class IdentityTest {

    @Test
    void toString_isMissionLevelSequenceInBrackets() {
        assertEquals("[rescue|1|4]", new Identity("rescue", 1, 4).toString());
    }

    @Test
    void order_isMissionThenLevelThenSequence() {
        List<Identity> sorted = List.of(new Identity("alpha", 2, 9), new Identity("rescue", 0, 5),
                new Identity("rescue", 1, 0), new Identity("rescue", 1, 3), new Identity("rescue", 2, 1));
        List<Identity> shuffled = new ArrayList<>(sorted);
        Collections.shuffle(shuffled, new java.util.Random(1));
        Collections.sort(shuffled);
        assertEquals(sorted, shuffled);
    }

    @Test
    void order_isConsistentWithEquals() {
        assertEquals(0, new Identity("m", 1, 2).compareTo(new Identity("m", 1, 2)));
    }

    @Test
    void negativeLevel_isRefused() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new Identity("m", -1, 0));
        assertEquals("Identity.level is -1; it must be 0 or more", e.getMessage());
    }
}
