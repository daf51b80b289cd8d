package net.smc.policy.runtime;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;

import net.smc.policy.api.Diagnostic;

/**
 * Where a cell's errors go: to the embedder's error reporter and to every listener added for a
 * while (a shell, a test); a run reports at most its limit of errors, and the count of the rest
 * when it finishes.
 */
final class ErrorReporter {
    private final Consumer<Diagnostic> errors;
    private final int maxErrorsPerRun;
    private final List<Consumer<Diagnostic>> listeners = new ArrayList<>();

    ErrorReporter(Consumer<Diagnostic> errors, int maxErrorsPerRun) {
        this.errors = errors;
        this.maxErrorsPerRun = maxErrorsPerRun;
    }

    void report(Diagnostic diagnostic) {
        for (Consumer<Diagnostic> listener : List.copyOf(listeners)) {
            listener.accept(diagnostic);
        }
        errors.accept(diagnostic);
    }

    /** Reports how many errors of a finished run were suppressed, if any were. */
    void finish(Execution ex) {
        long suppressed = ex.errorsSuppressed();
        if (suppressed > 0) {
            report(new Diagnostic(null, suppressed + " more error" + (suppressed == 1 ? "" : "s")
                    + " of this run suppressed (only the first " + maxErrorsPerRun + " are reported)"));
        }
    }

    void listen(Consumer<Diagnostic> listener) {
        listeners.add(listener);
    }

    void unlisten(Consumer<Diagnostic> listener) {
        listeners.remove(listener);
    }
}
