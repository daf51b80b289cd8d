package net.smc.sim.arena;

import java.util.List;
import java.util.stream.Collectors;

/** A world file that breaks at least one rule; it carries every error found, in file order. */
public final class ArenaException extends Exception {
    private final transient List<ArenaError> errors;

    ArenaException(List<ArenaError> errors) {
        super(errors.size() + " error" + (errors.size() == 1 ? "" : "s") + " in world file:\n"
                + errors.stream().map(ArenaError::toString).collect(Collectors.joining("\n")));
        this.errors = List.copyOf(errors);
    }

    public List<ArenaError> errors() {
        return errors;
    }
}
