package net.smc.core.cell;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;

import net.smc.core.cell.TeamState.Child;
import org.junit.jupiter.api.Test;

/**
 * The counts a subtree report carries: summed over the roles held, they are exactly the entries
 * above zero of the counts over every role of the mission, in the same order (the mission's roles
 * breadth-first, then other names as first met), whatever the children report.
 */
class TeamCountsTest {
    private final Slots slots = new Slots(Missions.reconnaissance(), Scheme.DISTRIBUTED);
    private static final List<String> NAMES = List.of("commander", "surveyor", "aggregator", "hdetector", "relay",
            "stranger", "other");

    @Test
    void heldCountsAreTheFullCountsAboveZeroInTheSameOrder() {
        Random random = new Random(3);
        for (int round = 0; round < 2_000; round++) {
            List<Seat> own = seats(random);
            List<Child> children = new ArrayList<>();
            for (int i = random.nextInt(5); i > 0; i--) {
                Child c = new Child("v" + i);
                if (random.nextBoolean()) {
                    Map<String, Integer> subtree = new LinkedHashMap<>();
                    for (int k = random.nextInt(4); k > 0; k--) {
                        subtree.put(NAMES.get(random.nextInt(NAMES.size())), random.nextInt(5) - 1);
                    }
                    c.subtree = subtree;
                } else {
                    c.seats = seats(random);
                }
                children.add(c);
            }
            Map<String, Integer> expected = new LinkedHashMap<>();
            TeamCounts.subtreeCounts(slots, own, children).forEach((role, n) -> {
                if (n > 0) {
                    expected.put(role, n);
                }
            });
            Map<String, Integer> held = TeamCounts.heldSubtreeCounts(slots, own, children);
            assertEquals(List.copyOf(expected.entrySet()), List.copyOf(held.entrySet()), "round " + round);
        }
    }

    private static List<Seat> seats(Random random) {
        List<Seat> out = new ArrayList<>();
        for (int i = random.nextInt(3); i > 0; i--) {
            out.add(new Seat(NAMES.get(random.nextInt(NAMES.size())), random.nextInt(2)));
        }
        return out;
    }
}
