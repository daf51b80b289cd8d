package net.smc.core.capability;

import java.util.List;

/**
 * An operation a task offers: its name and the Java simple names of its argument types, in order
 * (e.g. {@code moveTo} with {@code [double, double]}).
 */
public record OperationDescription(String name, List<String> argumentTypes) {
    public OperationDescription {
        argumentTypes = List.copyOf(argumentTypes);
    }
}
