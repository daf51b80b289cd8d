package net.smc.policy.runtime;

/**
 * Sees every event delivered at the managed object it was added to
 * ({@link ManagedObject#addObserver}), after that node's obligation policies, whatever its
 * template. Event forwarders are observers.
 */
@FunctionalInterface
public interface EventObserver {

    /**
     * Called during delivery, in the delivering run; an error thrown here reaches the raising
     * statement unless the observer contains it.
     */
    void observe(Execution ex, EventTemplate template, Object[] values);
}
