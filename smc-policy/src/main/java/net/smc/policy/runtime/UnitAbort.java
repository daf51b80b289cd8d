package net.smc.policy.runtime;

import net.smc.policy.api.PonderError;
/**
 * A runtime error that stops the whole unit even inside a policy, which otherwise contains
 * errors: a limit of the unit was hit (steps), or the stack ran out.
 */
public final class UnitAbort extends PonderError {
    public UnitAbort(String message) {
        super(message);
    }
}
