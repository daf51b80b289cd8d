package net.smc.core.router;

import java.util.Arrays;
import java.util.HashMap;
import java.util.Iterator;
import java.util.Map;
import java.util.function.Consumer;
import net.smc.core.message.MessageType;

/**
 * The router's dispatch table and exclusion table, and the rules that keep them canonical as
 * subscribers register and de-register (the set algebra described on {@link MessageRouter}):
 * <ul>
 *   <li>a pair entry (type from source) exists only where no aggregate registration (the whole
 *       type, or the whole source) of the same subscriber covers it;</li>
 *   <li>an exclusion entry exists only where an aggregate covers it;</li>
 *   <li>a source row exists only while it holds an entry.</li>
 * </ul>
 * So the tables stay as small as the registrations, and the receivers of (T, S) are always
 * {@code (byType[T] | row(S).all | row(S).pairs[T]) & ~row(S).excluded[T]}. Arguments are
 * checked by the router.
 */
final class RoutingTables {
    static final int TYPES = MessageType.values().length;

    /** Dispatch table, by type: subscribers registered for every packet of that type. */
    final long[][] byType = new long[TYPES][];
    /** Dispatch table by source, and the exclusion table, one row per source. */
    final Map<String, SourceRow> bySource = new HashMap<>();
    final RoleSlots slots = new RoleSlots();

    RoutingTables() {
        Arrays.fill(byType, CopyOnWriteBits.EMPTY);
    }

    void addType(Subscriber subscriber, int t) {
        int slot = slots.acquire(subscriber);
        byType[t] = CopyOnWriteBits.with(byType[t], slot);
        forEachRow(row -> {
            row.pairs[t] = CopyOnWriteBits.without(row.pairs[t], slot);
            row.excluded[t] = CopyOnWriteBits.without(row.excluded[t], slot);
        });
    }

    void addSource(Subscriber subscriber, String source) {
        int slot = slots.acquire(subscriber);
        SourceRow row = rowFor(source);
        row.all = CopyOnWriteBits.with(row.all, slot);
        for (int t = 0; t < TYPES; t++) {
            row.pairs[t] = CopyOnWriteBits.without(row.pairs[t], slot);
            row.excluded[t] = CopyOnWriteBits.without(row.excluded[t], slot);
        }
    }

    void addPair(Subscriber subscriber, int t, String source) {
        int slot = slots.acquire(subscriber);
        SourceRow row = rowFor(source);
        if (coveredByAggregate(slot, t, row)) {
            row.excluded[t] = CopyOnWriteBits.without(row.excluded[t], slot);
        } else {
            row.pairs[t] = CopyOnWriteBits.with(row.pairs[t], slot);
        }
        dropIfEmpty(source, row);
    }

    void removeType(Subscriber subscriber, int t) {
        int slot = slots.slotOf(subscriber);
        if (slot < 0) {
            return;
        }
        byType[t] = CopyOnWriteBits.without(byType[t], slot);
        forEachRow(row -> {
            row.pairs[t] = CopyOnWriteBits.without(row.pairs[t], slot);
            row.excluded[t] = CopyOnWriteBits.set(row.excluded[t], slot, CopyOnWriteBits.has(row.all, slot));
        });
    }

    void removeSource(Subscriber subscriber, String source) {
        int slot = slots.slotOf(subscriber);
        if (slot < 0 || !bySource.containsKey(source) && !registeredForAnyType(slot)) {
            return;
        }
        SourceRow row = rowFor(source);
        row.all = CopyOnWriteBits.without(row.all, slot);
        for (int t = 0; t < TYPES; t++) {
            row.pairs[t] = CopyOnWriteBits.without(row.pairs[t], slot);
            row.excluded[t] = CopyOnWriteBits.set(row.excluded[t], slot, CopyOnWriteBits.has(byType[t], slot));
        }
        dropIfEmpty(source, row);
    }

    void removePair(Subscriber subscriber, int t, String source) {
        int slot = slots.slotOf(subscriber);
        if (slot < 0) {
            return;
        }
        SourceRow row = bySource.get(source);
        boolean covered = coveredByAggregate(slot, t, row);
        if (row == null && !covered) {
            return;
        }
        row = rowFor(source);
        row.pairs[t] = CopyOnWriteBits.without(row.pairs[t], slot);
        row.excluded[t] = CopyOnWriteBits.set(row.excluded[t], slot, covered);
        dropIfEmpty(source, row);
    }

    void removeAll(Subscriber subscriber) {
        int slot = slots.slotOf(subscriber);
        if (slot < 0) {
            return;
        }
        for (int t = 0; t < TYPES; t++) {
            byType[t] = CopyOnWriteBits.without(byType[t], slot);
        }
        forEachRow(row -> {
            row.all = CopyOnWriteBits.without(row.all, slot);
            for (int t = 0; t < TYPES; t++) {
                row.pairs[t] = CopyOnWriteBits.without(row.pairs[t], slot);
                row.excluded[t] = CopyOnWriteBits.without(row.excluded[t], slot);
            }
        });
        slots.release(subscriber);
    }

    boolean receives(Subscriber subscriber, int t, String source) {
        int slot = slots.slotOf(subscriber);
        if (slot < 0) {
            return false;
        }
        SourceRow row = bySource.get(source);
        if (row == null) {
            return CopyOnWriteBits.has(byType[t], slot);
        }
        return (CopyOnWriteBits.has(byType[t], slot) || CopyOnWriteBits.has(row.all, slot) || CopyOnWriteBits.has(row.pairs[t], slot))
                && !CopyOnWriteBits.has(row.excluded[t], slot);
    }

    private boolean coveredByAggregate(int slot, int t, SourceRow row) {
        return CopyOnWriteBits.has(byType[t], slot) || row != null && CopyOnWriteBits.has(row.all, slot);
    }

    private boolean registeredForAnyType(int slot) {
        for (long[] bits : byType) {
            if (CopyOnWriteBits.has(bits, slot)) {
                return true;
            }
        }
        return false;
    }

    private SourceRow rowFor(String source) {
        return bySource.computeIfAbsent(source, s -> new SourceRow());
    }

    private void dropIfEmpty(String source, SourceRow row) {
        if (row.isEmpty()) {
            bySource.remove(source);
        }
    }

    /** Applies a change to every source row, dropping rows it leaves empty. */
    private void forEachRow(Consumer<SourceRow> change) {
        Iterator<SourceRow> it = bySource.values().iterator();
        while (it.hasNext()) {
            SourceRow row = it.next();
            change.accept(row);
            if (row.isEmpty()) {
                it.remove();
            }
        }
    }
}
