package net.smc.policy;

import net.smc.policy.api.Diagnostic;
import java.util.List;

/**
 * How a unit ended, the value of its last statement when it ran to the end, and the diagnostics
 * reported while it ran (its own errors and those of the policies it triggered; they also went to
 * the cell's error reporter).
 *
 * @param status      what happened
 * @param value       the last statement's value ({@code null} unless {@link Status#OK})
 * @param diagnostics what was reported while the unit ran, in order
 */
public record RunResult(Status status, Object value, List<Diagnostic> diagnostics) {

    public RunResult {
        diagnostics = List.copyOf(diagnostics);
    }

    public enum Status {
        /** Every statement ran. */
        OK,
        /** The unit had syntax errors; nothing ran. */
        SYNTAX_ERROR,
        /** A statement failed; the rest of the unit did not run. */
        RUNTIME_ERROR,
        /** {@code root exit} ran, now or in an earlier unit; the cell runs nothing more. */
        EXITED
    }

    public boolean ok() {
        return status == Status.OK;
    }
}
