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
        // Each takes its own share in ring order from its start.
        for (int slot = 0; slot < 2; slot++) {
            List<String> order = slot == 0 ? first : second;
            List<String> own = order.stream().filter(v -> SiblingOrder.shareOf(v, 2) == 0 == (order == first)).toList();
            List<String> ringOrder = new ArrayList<>(own);
            long start = SiblingOrder.startOf(slot, 2);
            ringOrder.sort((a, b) -> Long.compareUnsigned(SiblingOrder.key(a) - start, SiblingOrder.key(b) - start));
            assertEquals(ringOrder, order.subList(0, own.size()));
        }
    }

    /**
     * A sibling whose own share ran out goes on with the other's share: not in the ring order its
     * owner takes it in, which would send it for the very vehicle the owner asks next, every time,
     * but in an order of its own. Over 200 sets of heard vehicles, the short sibling's first spare
     * is the owner's first pick in about one set in the share's size, not in every one.
     */
    @Test
    void aSiblingShortOfVehicles_doesNotGoForTheVehicleTheOwnerOfTheShareAsksNext() {
        java.util.Random random = new java.util.Random(7);
        int same = 0;
        int sets = 0;
        while (sets < 200) {
            List<String> heard = new ArrayList<>();
            for (int i = 0; i < 60; i++) {
                if (random.nextInt(3) == 0) {
                    heard.add("uav-" + i);
                }
            }
            List<String> owner = SiblingOrder.of(heard, new Seat("hdetector", 1), distributed);
            List<String> shortOne = SiblingOrder.of(heard, new Seat("hdetector", 0), distributed);
            List<String> spares = shortOne.stream().filter(v -> SiblingOrder.shareOf(v, 2) == 1).toList();
            if (spares.size() < 4) {
                continue;
            }
            sets++;
            assertEquals(owner.get(0), owner.stream().filter(v -> SiblingOrder.shareOf(v, 2) == 1).findFirst().orElseThrow());
            if (spares.get(0).equals(owner.get(0))) {
                same++;
            }
        }
        assertTrue(same < 60, same + " of 200 sets: the short sibling went first for the owner's first pick");
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
}
