package net.smc.policy.api;

/** An obligation (event-condition-action) or authorisation policy. */
public interface PolicyHandle extends Handle {

    /** Whether it is an obligation policy (else an authorisation policy). */
    boolean isObligation();

    /** Whether it is active. */
    boolean active();

    /** Activates or deactivates it; answers the new state. */
    boolean active(boolean on);

    /** Deactivates it and, for an obligation policy, detaches it from every object it is attached to. */
    void retire();
}
