package net.smc.policy;

/**
 * How a unit ended, and the value of its last statement when it ran to the end.
 *
 * @param status what happened
 * @param value  the last statement's value ({@code null} unless {@link Status#OK})
 */
public record RunResult(Status status, Object value) {

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
