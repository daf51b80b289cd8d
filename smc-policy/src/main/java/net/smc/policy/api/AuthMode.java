package net.smc.policy.api;

/** Whether a cell checks authorisation policies, and its default decision when none matches. */
public enum AuthMode {
    /** No checking at all. */
    OFF,
    /** Checking on; allow when no policy decides. */
    ALLOW,
    /** Checking on; deny when no policy decides. */
    DENY
}
