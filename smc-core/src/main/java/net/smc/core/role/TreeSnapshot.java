package net.smc.core.role;

import java.math.BigDecimal;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Collections;
import java.util.IdentityHashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import net.smc.policy.api.DomainHandle;
import net.smc.policy.api.Handle;

/**
 * The entries of every domain reachable from root at one moment. The Role-Manager takes one before
 * a load, to put the tree back exactly if the load fails, and one around each policy file, to see
 * what the file added or changed.
 */
final class TreeSnapshot {
    private final Map<DomainHandle, LinkedHashMap<String, Object>> domains;

    private TreeSnapshot(Map<DomainHandle, LinkedHashMap<String, Object>> domains) {
        this.domains = domains;
    }

    static TreeSnapshot of(DomainHandle root) {
        Map<DomainHandle, LinkedHashMap<String, Object>> found = new IdentityHashMap<>();
        ArrayDeque<DomainHandle> queue = new ArrayDeque<>();
        queue.add(root);
        while (!queue.isEmpty()) {
            DomainHandle d = queue.poll();
            if (found.containsKey(d)) {
                continue;
            }
            found.put(d, new LinkedHashMap<>(d.entries()));
            for (Object value : d.entries().values()) {
                if (value instanceof DomainHandle child) {
                    queue.add(child);
                }
            }
        }
        return new TreeSnapshot(found);
    }

    /** A domain's entries in this snapshot (empty if it was not reachable then). */
    Map<String, Object> entriesOf(DomainHandle d) {
        Map<String, Object> entries = domains.get(d);
        return entries == null ? Map.of() : Collections.unmodifiableMap(entries);
    }

    /** Every domain reachable from {@code start} in this snapshot ({@code start} included). */
    Set<DomainHandle> below(DomainHandle start) {
        Set<DomainHandle> out = Collections.newSetFromMap(new IdentityHashMap<>());
        ArrayDeque<DomainHandle> queue = new ArrayDeque<>();
        queue.add(start);
        while (!queue.isEmpty()) {
            DomainHandle d = queue.poll();
            if (out.add(d)) {
                Map<String, Object> entries = domains.get(d);
                for (Object value : entries == null ? d.entries().values() : entries.values()) {
                    if (value instanceof DomainHandle child) {
                        queue.add(child);
                    }
                }
            }
        }
        return out;
    }

    /** One entry that a load added to a domain outside the role's own. */
    record Addition(DomainHandle domain, String name, Object value) {
        /** Removes the entry, unless something else has replaced it since. */
        void undo() {
            if (domain.get(name) == value) {
                domain.remove(name);
            }
        }
    }

    /** What happened between this snapshot and a later one, outside some domains. */
    record Changes(List<Addition> added, List<String> changed) {
    }

    /**
     * The entries replaced or removed in any domain of this snapshot (each described with its
     * path), and the entries added to those of them not in {@code ownDomains}.
     */
    Changes changesTo(TreeSnapshot later, Set<DomainHandle> ownDomains, DomainHandle root) {
        List<Addition> added = new ArrayList<>();
        List<String> changed = new ArrayList<>();
        for (Map.Entry<DomainHandle, LinkedHashMap<String, Object>> e : domains.entrySet()) {
            DomainHandle d = e.getKey();
            LinkedHashMap<String, Object> after = later.domains.get(d);
            if (after == null) {
                continue;
            }
            LinkedHashMap<String, Object> before = e.getValue();
            for (Map.Entry<String, Object> entry : before.entrySet()) {
                Object now = after.get(entry.getKey());
                if (now == null) {
                    changed.add("removed " + pathOf(d, root) + "/" + entry.getKey());
                } else if (!same(now, entry.getValue())) {
                    changed.add("replaced " + pathOf(d, root) + "/" + entry.getKey());
                }
            }
            for (Map.Entry<String, Object> entry : after.entrySet()) {
                if (!ownDomains.contains(d) && !before.containsKey(entry.getKey())) {
                    added.add(new Addition(d, entry.getKey(), entry.getValue()));
                }
            }
        }
        return new Changes(added, changed);
    }

    /**
     * Puts every domain of this snapshot back as it was, and empties the domains reachable now that
     * were not then (they were made by the failed load; emptying them also drops the parent links
     * they gave to older objects).
     */
    void restore(DomainHandle root) {
        TreeSnapshot now = of(root);
        for (Map.Entry<DomainHandle, LinkedHashMap<String, Object>> e : domains.entrySet()) {
            DomainHandle d = e.getKey();
            if (!sameEntries(d.entries(), e.getValue())) {
                d.removeAll();
                e.getValue().forEach(d::put);
            }
        }
        for (DomainHandle d : now.domains.keySet()) {
            if (!domains.containsKey(d)) {
                d.removeAll();
            }
        }
    }

    private static boolean sameEntries(Map<String, Object> a, Map<String, Object> b) {
        if (a.size() != b.size()) {
            return false;
        }
        var ia = a.entrySet().iterator();
        var ib = b.entrySet().iterator();
        while (ia.hasNext()) {
            var x = ia.next();
            var y = ib.next();
            if (!x.getKey().equals(y.getKey()) || !same(x.getValue(), y.getValue())) {
                return false;
            }
        }
        return true;
    }

    /** Identity for objects; equal numbers, strings and booleans count as the same value. */
    private static boolean same(Object a, Object b) {
        if (a == b) {
            return true;
        }
        if (a instanceof Handle || b instanceof Handle) {
            return false;
        }
        if (a instanceof BigDecimal x && b instanceof BigDecimal y) {
            return x.compareTo(y) == 0;
        }
        return (a instanceof String || a instanceof Boolean) && a.equals(b);
    }

    private static String pathOf(DomainHandle d, DomainHandle root) {
        String path = d == root ? "root" : d.path();
        return path == null ? "<a domain>" : path;
    }
}
