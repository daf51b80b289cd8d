package net.smc.policy.bench;

import java.util.ArrayList;
import java.util.List;
import net.smc.policy.api.AuthMode;
import net.smc.policy.PolicyEngine;
import net.smc.policy.api.Diagnostic;
import net.smc.policy.RunResult;

/** Small helpers shared by the benchmarks: cells that collect their errors, checks, generated texts. */
final class Bench {
    private Bench() {
    }

    /** A cell with the given authorisation mode whose errors are collected in {@code errors}. */
    static PolicyEngine cell(AuthMode mode, List<Diagnostic> errors) {
        return PolicyEngine.builder().auth(mode).errors(errors::add).build();
    }

    /** Runs a unit that must succeed. */
    static RunResult run(PolicyEngine cell, String name, String text, List<Diagnostic> errors) {
        RunResult result = cell.run(name, text);
        check(result.ok() && errors.isEmpty(), name + ": " + result.status() + " " + errors);
        return result;
    }

    static void check(boolean condition, String message) {
        if (!condition) {
            throw new IllegalStateException("benchmark check failed: " + message);
        }
    }

    /** {@code n} event templates {@code root/event/<prefix>0 ..} with attributes "name" and "level". */
    static String templates(String prefix, int n) {
        StringBuilder text = new StringBuilder();
        for (int i = 0; i < n; i++) {
            text.append("root/event at: \"").append(prefix).append(i)
                    .append("\" put: (root/factory/event create: #(\"name\" \"level\")).\n");
        }
        return text.toString();
    }

    /**
     * {@code n} active obligation policies {@code root/policy/<prefix>i}, the i-th reacting to
     * {@code root/event/<templatePrefix>i} with condition {@code level > 5} and an action that
     * stores the level in the hash {@code store} under {@code key}; the unit must make the variable
     * {@code store} (a hash) before this text.
     */
    static String policies(String prefix, String templatePrefix, int n, String key) {
        StringBuilder text = new StringBuilder();
        for (int i = 0; i < n; i++) {
            text.append("p := root/factory/ecapolicy create. p event: root/event/").append(templatePrefix).append(i)
                    .append("; condition: [:level | level > 5]; action: [:level | store at: \"").append(key)
                    .append("\" put: level]; active: true. root/policy at: \"").append(prefix).append(i)
                    .append("\" put: p.\n");
        }
        return text.toString();
    }

    static List<Diagnostic> errors() {
        return new ArrayList<>();
    }
}
