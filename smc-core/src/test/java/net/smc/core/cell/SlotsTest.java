package net.smc.core.cell;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HashSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;

import org.junit.jupiter.api.Test;

/** Seat arithmetic on the shipped reconnaissance mission (2 surveyors, 1 aggregator, 2 detectors, 2 relays). */
class SlotsTest {
    private final Slots distributed = new Slots(Missions.reconnaissance(), Scheme.DISTRIBUTED);
    private final Slots centralised = new Slots(Missions.reconnaissance(), Scheme.CENTRALISED);

    @Test
    void everySeatHasADistinctSequenceAndTheCommanderIsZero() {
        List<Seat> all = distributed.all();
        assertEquals(8, all.size());
        Set<Integer> sequences = new HashSet<>();
        all.forEach(s -> assertTrue(sequences.add(distributed.sequence(s)), "sequence of " + s + " repeats"));
        assertEquals(0, distributed.sequence(Slots.commanderSeat()));
        assertEquals(List.of("commander", "surveyor", "aggregator", "hdetector", "relay"), distributed.roles());
    }

    @Test
    void distributedOwnershipFollowsTheTreeOfFigureFive() {
        assertEquals(Optional.of(new Seat("commander", 0)), distributed.owner(new Seat("surveyor", 1)));
        assertEquals(Optional.of(new Seat("surveyor", 0)), distributed.owner(new Seat("hdetector", 0)));
        assertEquals(Optional.of(new Seat("surveyor", 1)), distributed.owner(new Seat("relay", 1)));
        assertEquals(List.of(new Seat("hdetector", 1), new Seat("relay", 1)), distributed.ownedBy(new Seat("surveyor", 1)));
        assertEquals(2, distributed.level("relay"));
        assertEquals(Optional.empty(), distributed.owner(Slots.commanderSeat()));
    }

    @Test
    void centralisedOwnershipIsFlat() {
        for (Seat s : centralised.all()) {
            if (!s.role().equals("commander")) {
                assertEquals(Optional.of(Slots.commanderSeat()), centralised.owner(s));
                assertEquals(1, centralised.level(s.role()));
            }
        }
        assertEquals(7, centralised.ownedBy(Slots.commanderSeat()).size());
    }

    @Test
    void secondarySeatsAreHostedByTheMatchingPrimarySeat() {
        assertEquals(Optional.of(new Seat("surveyor", 1)), distributed.host(new Seat("relay", 1)));
        assertEquals(Optional.empty(), distributed.host(new Seat("aggregator", 0)));
    }

    @Test
    void minimalSeatsComeFirstThenRolesBreadthFirst() {
        assertTrue(distributed.compare(new Seat("surveyor", 1), new Seat("aggregator", 0)) < 0);
        assertTrue(distributed.compare(new Seat("aggregator", 0), new Seat("hdetector", 0)) < 0);
        assertTrue(distributed.minimal(new Seat("relay", 1)));
    }

    @Test
    void afterAssignKeepsWhatMayShareAVehicleAndDropsTheRest() {
        List<Seat> surveyorWithBoth = distributed.afterAssign(List.of(new Seat("hdetector", 0), new Seat("relay", 0)),
                new Seat("surveyor", 0));
        assertEquals(List.of(new Seat("surveyor", 0), new Seat("hdetector", 0), new Seat("relay", 0)), surveyorWithBoth);
        List<Seat> moved = distributed.afterAssign(List.of(new Seat("aggregator", 0)), new Seat("surveyor", 1));
        assertEquals(List.of(new Seat("surveyor", 1)), moved, "an aggregator moved to survey stops aggregating");
        assertFalse(distributed.afterAssign(List.of(new Seat("relay", 0)), new Seat("relay", 1)).contains(new Seat("relay", 0)),
                "one seat a role per vehicle");
        assertNotEquals(distributed.sequence(new Seat("relay", 0)), distributed.sequence(new Seat("relay", 1)));
    }

    @Test
    void policyVersionsFollowTheTextAndRefuseAMismatch() {
        PolicyStore store = new PolicyStore();
        int v = PolicyStore.versionOf("p := 1.");
        assertNotEquals(v, PolicyStore.versionOf("p := 2."));
        assertTrue(v > 0);
        assertFalse(store.accept("policy:/x", v + 1, "p := 1."), "a text whose version does not match is refused");
        assertTrue(store.accept("policy:/x", v, "p := 1."));
        assertEquals(Optional.of(v), store.get("policy:/x", PolicyStore.ANY_VERSION).map(PolicyStore.Entry::version));
        assertTrue(store.get("policy:/x", v + 1).isEmpty());
    }
}
