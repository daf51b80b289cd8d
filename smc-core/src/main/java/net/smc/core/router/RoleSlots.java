package net.smc.core.router;

import java.util.Arrays;
import java.util.IdentityHashMap;

/**
 * Gives each subscriber a slot, its bit in the router's tables, and keeps the slot-to-subscriber
 * array that dispatch walks. Slots are reused lowest first once a subscriber is removed; the array
 * is replaced, never changed, so a dispatch in progress keeps the subscribers it started with.
 */
final class RoleSlots {
    private final IdentityHashMap<Subscriber, Integer> slots = new IdentityHashMap<>();
    private Subscriber[] bySlot = new Subscriber[0];

    /** The subscriber's slot, or -1. */
    int slotOf(Subscriber s) {
        Integer slot = slots.get(s);
        return slot == null ? -1 : slot;
    }

    /** The subscriber's slot, given one if it has none. */
    int acquire(Subscriber s) {
        Integer slot = slots.get(s);
        if (slot != null) {
            return slot;
        }
        int free = 0;
        while (free < bySlot.length && bySlot[free] != null) {
            free++;
        }
        Subscriber[] next = Arrays.copyOf(bySlot, Math.max(bySlot.length, free + 1));
        next[free] = s;
        bySlot = next;
        slots.put(s, free);
        return free;
    }

    void release(Subscriber s) {
        Integer slot = slots.remove(s);
        if (slot != null) {
            Subscriber[] next = bySlot.clone();
            next[slot] = null;
            bySlot = next;
        }
    }

    /** Slot to subscriber (null for a free slot); never changed once returned. */
    Subscriber[] snapshot() {
        return bySlot;
    }

    int size() {
        return slots.size();
    }
}
