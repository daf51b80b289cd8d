package net.smc.core.role;

/**
 * An operation a role expects a collaborating role to export (the paper's external interface,
 * item iv), such as the aggregator's {@code addHazard:x:y:} required by the hazard detector.
 */
public record RequiredOperation(String role, String selector) {
    public RequiredOperation {
        RoleNames.checkRole("role of a required operation", role);
        RoleNames.checkSelector("selector required from role '" + role + "'", selector);
    }
}
