package net.smc.core.role;

import java.util.List;

/**
 * A role could not be loaded; the cell is as it was before the attempt (nothing of the role was
 * left behind). Names the role, the part that failed (a policy by its URI or name, a task, an
 * interface) and every reason reported, diagnostics of the cell included.
 */
public final class RoleLoadException extends Exception {
    private final String role;
    private final String part;
    private final List<String> reasons;

    RoleLoadException(String role, String part, List<String> reasons) {
        super("role '" + role + "' was not loaded (the cell is as it was before): " + part + " failed: "
                + String.join("; ", reasons));
        this.role = role;
        this.part = part;
        this.reasons = List.copyOf(reasons);
    }

    public String role() {
        return role;
    }

    /** What failed, e.g. {@code policy 'policy:/roles/surveyor/mission'} or {@code task 'Explorer'}. */
    public String part() {
        return part;
    }

    /** Why, one entry per diagnostic or broken rule. */
    public List<String> reasons() {
        return reasons;
    }
}
