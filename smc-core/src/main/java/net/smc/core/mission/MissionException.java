package net.smc.core.mission;

import java.util.List;
import java.util.stream.Collectors;

/**
 * A mission instance (or its class) that breaks at least one rule. It carries every error found in
 * both files, not only the first, so that one run of {@code smc validate} lists them all.
 */
public final class MissionException extends Exception {
    private final transient List<MissionError> errors;

    MissionException(List<MissionError> errors) {
        super(errors.size() + " error" + (errors.size() == 1 ? "" : "s") + " in mission files:\n"
                + errors.stream().map(MissionError::toString).collect(Collectors.joining("\n")));
        this.errors = List.copyOf(errors);
    }

    /** Every error, class file first, each file's errors in the order of their position. */
    public List<MissionError> errors() {
        return errors;
    }
}
