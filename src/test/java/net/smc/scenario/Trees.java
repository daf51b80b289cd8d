package net.smc.scenario;

import java.util.Collections;
import java.util.IdentityHashMap;
import java.util.Map;
import java.util.Set;
import net.smc.policy.PolicyEngine;
import net.smc.policy.runtime.Domain;
import net.smc.policy.runtime.ManagedObject;

/** A domain tree as text: one line per entry, with each object's class and identity. */
final class Trees {
    private Trees() {
    }

    static String describe(Domain root) {
        StringBuilder out = new StringBuilder();
        describe(root, "root", out, Collections.newSetFromMap(new IdentityHashMap<>()));
        return out.toString();
    }

    private static void describe(Domain d, String path, StringBuilder out, Set<Domain> seen) {
        if (!seen.add(d)) {
            return;
        }
        for (Map.Entry<String, Object> e : d.entries().entrySet()) {
            Object v = e.getValue();
            out.append(path).append('/').append(e.getKey()).append(" = ")
                    .append(v instanceof ManagedObject m ? m.type().name() + "@" + System.identityHashCode(m) : PolicyEngine.print(v))
                    .append('\n');
            if (v instanceof Domain child) {
                describe(child, path + "/" + e.getKey(), out, seen);
            }
        }
    }
}
