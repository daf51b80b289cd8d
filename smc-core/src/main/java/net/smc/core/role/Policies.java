package net.smc.core.role;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Collections;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Set;
import net.smc.policy.runtime.AuthorisationPolicy;
import net.smc.policy.runtime.Domain;
import net.smc.policy.runtime.ManagedObject;
import net.smc.policy.runtime.ObligationPolicy;

/** Taking policies out of service, for a failed load and for a withdrawal. */
final class Policies {
    private Policies() {
    }

    /** Deactivates a policy and, for an obligation policy, detaches it from every node it is attached to. */
    static void retire(ManagedObject policy) {
        if (policy instanceof ObligationPolicy obligation) {
            obligation.active(false);
            for (ManagedObject node : obligation.attachments()) {
                obligation.detach(node);
            }
        } else if (policy instanceof AuthorisationPolicy authorisation) {
            authorisation.active(false);
        }
    }

    /** Every managed object reachable from root, root first. */
    static List<ManagedObject> reachable(Domain root) {
        List<ManagedObject> out = new ArrayList<>();
        Set<ManagedObject> seen = Collections.newSetFromMap(new IdentityHashMap<>());
        ArrayDeque<ManagedObject> queue = new ArrayDeque<>();
        queue.add(root);
        while (!queue.isEmpty()) {
            ManagedObject at = queue.poll();
            if (!seen.add(at)) {
                continue;
            }
            out.add(at);
            if (at instanceof Domain d) {
                for (Object value : d.entries().values()) {
                    if (value instanceof ManagedObject m) {
                        queue.add(m);
                    }
                }
            }
        }
        return out;
    }

    /** Every policy stored anywhere under {@code start}. */
    static List<ManagedObject> under(Domain start) {
        List<ManagedObject> out = new ArrayList<>();
        for (ManagedObject m : reachable(start)) {
            if (m instanceof ObligationPolicy || m instanceof AuthorisationPolicy) {
                out.add(m);
            }
        }
        return out;
    }
}
