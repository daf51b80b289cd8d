package net.smc.sim.task;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import net.smc.core.capability.EventDescription;
import net.smc.core.task.Task;
import net.smc.policy.PolicyEngine;
import net.smc.policy.api.Diagnostic;
import net.smc.policy.RunResult;

/**
 * Binds tasks to a policy cell and records every event they raise, through an obligation policy
 * per event that prints {@code event|attr|attr...}: what a policy would see.
 */
final class EventLog {
    final List<String> lines = new ArrayList<>();
    final List<Diagnostic> errors = new ArrayList<>();
    final PolicyEngine cell = PolicyEngine.builder().output(lines::add).errors(errors::add).build();

    EventLog watch(Task task) throws Exception {
        task.bind(cell);
        for (EventDescription e : task.describe().events()) {
            List<String> names = e.attributes().stream().map(EventDescription.Attribute::name).toList();
            StringBuilder params = new StringBuilder();
            StringBuilder body = new StringBuilder("\"" + e.name() + "\"");
            for (String n : names) {
                params.append(':').append(n).append(' ');
                body.append(" + \"|\" + ").append(n);
            }
            RunResult r = cell.run("watch.p2", "p := root/factory/ecapolicy create.\n"
                    + "p event: /event/" + e.name() + "; action: [" + params + "| root print: " + body + "].\n"
                    + "p active: true.\n");
            assertTrue(r.ok() && errors.isEmpty(), "watching " + e.name() + ": " + errors);
        }
        return this;
    }

    /** The events of that name, each its attribute values as printed. */
    List<String[]> of(String event) {
        List<String[]> found = new ArrayList<>();
        for (String line : lines) {
            String[] parts = line.split("\\|", -1);
            if (parts[0].equals(event)) {
                String[] values = new String[parts.length - 1];
                System.arraycopy(parts, 1, values, 0, values.length);
                found.add(values);
            }
        }
        return found;
    }

    void assertNoErrors() {
        assertEquals(List.of(), errors);
    }

    static double num(String s) {
        return Double.parseDouble(s);
    }
}
