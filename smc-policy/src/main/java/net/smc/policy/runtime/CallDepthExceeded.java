package net.smc.policy.runtime;

import net.smc.policy.api.PonderError;
/**
 * The call depth limit was hit: a block recursion or an event loop ran away. Inside a chain of
 * policies fired by events, no policy but the outermost one contains it, so a loop that raises
 * its event more than once is cut off at its first overflow and reported once, rather than
 * unwinding one level and overflowing again at every branch of the loop.
 */
final class CallDepthExceeded extends PonderError {
    CallDepthExceeded(int limit) {
        super("call depth limit of " + limit + " exceeded");
    }
}
