package net.smc.policy.lang;

import java.util.List;

/** A parsed unit: its statements, ready to run, or the syntax errors that stop it from running. */
public record Unit(String source, List<Node> statements, List<SyntaxError> errors) {
    public Unit {
        statements = List.copyOf(statements);
        errors = List.copyOf(errors);
    }

    public boolean hasErrors() {
        return !errors.isEmpty();
    }
}
