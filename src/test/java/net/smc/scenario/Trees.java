package net.smc.scenario;

import java.util.Collections;
import java.util.IdentityHashMap;
import java.util.Map;
import java.util.Set;
import net.smc.policy.PolicyEngine;
import net.smc.policy.api.DomainHandle;
import net.smc.policy.api.Handle;

/** A domain tree as text: one line per entry, with each object's class and identity. */
final class Trees {
    private Trees() {
    }

    static String describe(DomainHandle root) {
        StringBuilder out = new StringBuilder();
        describe(root, "root", out, Collections.newSetFromMap(new IdentityHashMap<>()));
        return out.toString();
    }

    private static void describe(DomainHandle d, String path, StringBuilder out, Set<DomainHandle> seen) {
        if (!seen.add(d)) {
            return;
        }
        for (Map.Entry<String, Object> e : d.entries().entrySet()) {
            Object v = e.getValue();
            out.append(path).append('/').append(e.getKey()).append(" = ")
                    .append(v instanceof Handle m ? m.className() + "@" + System.identityHashCode(m) : PolicyEngine.print(v))
                    .append('\n');
            if (v instanceof DomainHandle child) {
                describe(child, path + "/" + e.getKey(), out, seen);
            }
        }
    }
}
