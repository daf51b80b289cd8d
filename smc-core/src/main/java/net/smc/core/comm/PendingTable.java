package net.smc.core.comm;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * The sender's state table: outstanding critical messages by id. Ids are unique per cell, so the
 * id alone finds the message an Ack confirms. Only lookup by id is needed on the hot path; the
 * send order, needed when the sender stops, is recovered by sorting ids (they grow monotonically).
 */
final class PendingTable {
    private final Map<Long, Pending> byId = new HashMap<>();

    void add(Pending p) {
        if (byId.putIfAbsent(p.id, p) != null) {
            throw new IllegalStateException("message id " + p.id + " is already outstanding; ids must be unique per cell");
        }
    }

    Pending get(long id) {
        return byId.get(id);
    }

    Pending remove(long id) {
        return byId.remove(id);
    }

    int size() {
        return byId.size();
    }

    /** Removes every outstanding message and returns them in send order. */
    List<Pending> drain() {
        List<Pending> all = new ArrayList<>(byId.values());
        all.sort((a, b) -> Long.compare(a.id, b.id));
        byId.clear();
        return all;
    }
}
