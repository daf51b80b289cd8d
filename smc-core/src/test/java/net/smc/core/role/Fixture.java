package net.smc.core.role;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Collections;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import net.smc.policy.api.AuthMode;
import net.smc.policy.PolicyEngine;
import net.smc.policy.api.Diagnostic;
import net.smc.policy.api.PolicyRepository;
import net.smc.policy.RunResult;
import net.smc.policy.runtime.AuthorisationPolicy;
import net.smc.policy.api.DomainHandle;
import net.smc.policy.api.Handle;
import net.smc.policy.runtime.ObligationPolicy;

/**
 * A booted cell (authorisation on, default deny after boot) with a Role-Manager, recording what
 * the cell prints, the errors it reports and the re-assignments asked for. Boot makes the event
 * {@code root/event/go} (attribute {@code n}).
 */
final class Fixture {
    final List<String> out = new ArrayList<>();
    final List<Diagnostic> errors = new ArrayList<>();
    final List<String> reassigned = new ArrayList<>();
    final PolicyEngine cell;
    final RoleManager roles;

    Fixture() {
        this(null, "");
    }

    /** A cell whose boot unit also runs {@code moreBoot}. */
    Fixture(PolicyRepository repository, String moreBoot) {
        PolicyEngine.Builder builder = PolicyEngine.builder().output(out::add).errors(errors::add).auth(AuthMode.DENY);
        if (repository != null) {
            builder.repository(repository);
        }
        cell = builder.build();
        RunResult boot = cell.run("boot", "root/event at: \"go\" put: (root/factory/event create: #(\"n\")).\n" + moreBoot);
        assertTrue(boot.ok(), () -> "boot failed: " + boot.diagnostics());
        cell.endBoot();
        roles = RoleManager.builder(cell)
                .reassignment((manager, role, scheme) -> reassigned.add(manager + " reassigns " + role + " by " + scheme))
                .build();
    }

    /** An inline obligation policy file of role {@code role}: on go, print {@code label} and n. */
    static PolicySource printer(String role, String label) {
        return PolicySource.text(label, """
                p := root/factory/ecapolicy create.
                p event: root/event/go; action: [:n | root print: "%s " + n].
                root/role/%s/policy at: "%s" put: p.
                """.formatted(label, role, label));
    }

    void go(int n) {
        assertTrue(cell.raise("root/event/go", n), () -> "raise failed: " + errors);
    }

    /** Runs a top-level unit that must succeed. */
    Object run(String text) {
        RunResult result = cell.run("test", text);
        assertTrue(result.ok(), () -> "unit failed: " + result.diagnostics());
        return result.value();
    }

    /**
     * The whole domain tree from root, one line per entry: its path, the class of its value and
     * the value's identity (or printed form for plain values), and whether a policy is active.
     * Two equal descriptions mean the same objects in the same places.
     */
    static String tree(DomainHandle root) {
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
            String at = path + "/" + e.getKey();
            out.append(at).append(" = ");
            if (v instanceof Handle m) {
                out.append(m.className()).append('@').append(System.identityHashCode(m));
                if (v instanceof ObligationPolicy p) {
                    out.append(p.isActive() ? " active" : " inactive");
                } else if (v instanceof AuthorisationPolicy p) {
                    out.append(p.active() ? " active" : " inactive");
                }
            } else {
                out.append(PolicyEngine.print(v));
            }
            out.append('\n');
            if (v instanceof DomainHandle child) {
                describe(child, at, out, seen);
            }
        }
    }
}
