package net.smc.core.role;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Collections;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Set;
import net.smc.policy.api.PolicyHandle;
import net.smc.policy.api.DomainHandle;
import net.smc.policy.api.Handle;

/** Taking policies out of service, for a failed load and for a withdrawal. */
final class Policies {
    private Policies() {
    }

    /** Deactivates a policy and, for an obligation policy, detaches it from every node it is attached to. */
    static void retire(Handle policy) {
        if (policy instanceof PolicyHandle p) {
            p.retire();
        }
    }

    /** Every managed object reachable from root, root first. */
    static List<Handle> reachable(DomainHandle root) {
        List<Handle> out = new ArrayList<>();
        Set<Handle> seen = Collections.newSetFromMap(new IdentityHashMap<>());
        ArrayDeque<Handle> queue = new ArrayDeque<>();
        queue.add(root);
        while (!queue.isEmpty()) {
            Handle at = queue.poll();
            if (!seen.add(at)) {
                continue;
            }
            out.add(at);
            if (at instanceof DomainHandle d) {
                for (Object value : d.entries().values()) {
                    if (value instanceof Handle m) {
                        queue.add(m);
                    }
                }
            }
        }
        return out;
    }

    /** Every policy stored anywhere under {@code start}. */
    static List<Handle> under(DomainHandle start) {
        List<Handle> out = new ArrayList<>();
        for (Handle m : reachable(start)) {
            if (m instanceof PolicyHandle) {
                out.add(m);
            }
        }
        return out;
    }
}
