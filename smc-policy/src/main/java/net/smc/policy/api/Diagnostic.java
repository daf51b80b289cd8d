package net.smc.policy.api;

import net.smc.policy.lang.SourcePos;

/**
 * An error the cell reports: a syntax error, a runtime error at the failing send, or a contained
 * policy error. Prints as {@code file:line:col: message}.
 */
public record Diagnostic(SourcePos pos, String message) {

    @Override
    public String toString() {
        return pos == null ? message : pos + ": " + message;
    }
}
