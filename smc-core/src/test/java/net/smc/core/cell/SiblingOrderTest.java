package net.smc.core.cell;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

import org.junit.jupiter.api.Test;

/**
 * The order in which a manager puts the vehicles that answered it to its policies, on the shipped
 * reconnaissance mission: the two surveyors own hdetector seats 0 and 1 (and relay seats 0 and 1).
 */
class SiblingOrderTest {
    private final Slots distributed = new Slots(Missions.reconnaissance(), Scheme.DISTRIBUTED);
    private static final List<String> HEARD = List.of("uav-7", "uav-2", "uav-12", "uav-5");

    @Test
    void siblingsThatHeardTheSameVehicles_eachBeginInItsOwnShareOfTheRing() {
        List<String> heard = new ArrayList<>();
        for (int i = 0; i < 40; i++) {
            heard.add("uav-" + i);
        }
        List<String> first = SiblingOrder.of(heard, new Seat("hdetector", 0), distributed);
        List<String> second = SiblingOrder.of(heard, new Seat("hdetector", 1), distributed);
        assertNotEquals(first.get(0), second.get(0));
        long half = Long.divideUnsigned(-1L, 2);
        assertTrue(Long.compareUnsigned(SiblingOrder.key(first.get(0)) - SiblingOrder.startOf(0, 2), half) < 0);
        assertTrue(Long.compareUnsigned(SiblingOrder.key(second.get(0)) - SiblingOrder.startOf(1, 2), half) < 0);
        // The same cycle, entered at different places.
        assertEquals(second, rotate(first, first.indexOf(second.get(0))));
    }

    @Test
    void everyVehicleLiesInOneSiblingsShare_theOneWhoseOrderBeginsWithIt() {
        List<String> heard = new ArrayList<>();
        for (int i = 0; i < 40; i++) {
            heard.add("uav-" + i);
        }
        for (String vehicle : heard) {
            boolean first = SiblingOrder.inOwnShare(vehicle, new Seat("hdetector", 0), distributed);
            boolean second = SiblingOrder.inOwnShare(vehicle, new Seat("hdetector", 1), distributed);
            assertTrue(first != second, vehicle);
            assertEquals(first ? 0 : 1, SiblingOrder.shareOf(vehicle, 2));
        }
        // Surveyor 0's order begins with its own share's vehicles, then the others'.
        List<String> order = SiblingOrder.of(heard, new Seat("relay", 0), distributed);
        int own = (int) heard.stream().filter(v -> SiblingOrder.shareOf(v, 2) == 0).count();
        assertTrue(own > 0 && own < heard.size(), "both shares hold some of 40 vehicles");
        assertTrue(order.subList(0, own).stream().allMatch(v -> SiblingOrder.inOwnShare(v, new Seat("relay", 0), distributed)));
        assertTrue(order.subList(own, heard.size()).stream().noneMatch(v -> SiblingOrder.inOwnShare(v, new Seat("relay", 0), distributed)));
    }

    @Test
    void shares_splitTheRingEvenly_andAManagerWithoutSiblingsOwnsItAll() {
        int[] counts = new int[10];
        for (int i = 0; i < 10_000; i++) {
            counts[SiblingOrder.shareOf("b0l3n" + i, 10)]++;
        }
        for (int c : counts) {
            assertTrue(c > 850 && c < 1150, () -> java.util.Arrays.toString(counts));
        }
        assertEquals(0, SiblingOrder.shareOf("uav-7", 1));
        Slots centralised = new Slots(Missions.centralised(), Scheme.CENTRALISED);
        assertTrue(HEARD.stream().allMatch(v -> SiblingOrder.inOwnShare(v, new Seat("relay", 1), centralised)));
    }

    @Test
    void idsThatDifferOnlyInTheirLastCharacter_spreadRoundTheRing() {
        Set<Long> eighths = new HashSet<>();
        for (int i = 0; i < 8; i++) {
            eighths.add(SiblingOrder.key("b0l3n" + i) >>> 61);
        }
        assertTrue(eighths.size() >= 4, () -> "eighths of the ring taken by b0l3n0..b0l3n7: " + eighths);
    }

    @Test
    void theOrderDependsOnWhoAnswered_notOnTheOrderTheyAnswered() {
        List<String> reversed = new ArrayList<>(HEARD);
        java.util.Collections.reverse(reversed);
        assertEquals(SiblingOrder.of(HEARD, new Seat("relay", 1), distributed),
                SiblingOrder.of(reversed, new Seat("relay", 1), distributed));
        assertEquals(new HashSet<>(HEARD), new HashSet<>(SiblingOrder.of(HEARD, new Seat("relay", 1), distributed)));
    }

    @Test
    void theSeatsOfOneManager_giveOnePlace() {
        // hdetector 1 and relay 1 are both owned by surveyor 1.
        assertEquals(SiblingOrder.of(HEARD, new Seat("hdetector", 1), distributed),
                SiblingOrder.of(HEARD, new Seat("relay", 1), distributed));
    }

    @Test
    void aSingleManager_takesTheCommonOrderFromItsStart() {
        Slots centralised = new Slots(Missions.centralised(), Scheme.CENTRALISED);
        List<String> common = new ArrayList<>(HEARD);
        common.sort(java.util.Comparator.comparingLong(SiblingOrder::key));
        assertEquals(common, SiblingOrder.of(HEARD, new Seat("relay", 1), centralised));
    }

    private static List<String> rotate(List<String> list, int by) {
        List<String> rotated = new ArrayList<>();
        for (int i = 0; i < list.size(); i++) {
            rotated.add(list.get((i + by) % list.size()));
        }
        return rotated;
    }
}
