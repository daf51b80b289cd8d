package net.smc.core.transport;

/**
 * The time as a cell sees it, in <b>milliseconds</b>. Every duration in this package and in the
 * protocols built on it (delays, timeouts, latencies) is a {@code long} count of milliseconds, and
 * every method that takes one says so in its name.
 *
 * <p>Milliseconds because the protocols' times (heartbeats, failure timeouts, radio latency) are
 * milliseconds to minutes, and because the policy engine's clock ({@code net.smc.policy.PolicyEngine}) is
 * milliseconds too: {@code PolicyEngine.builder().clock(clock::nowMillis)} hands a cell's clock to it.
 *
 * <p>The value never goes backwards. In simulation it is virtual time ({@code SimulationScheduler},
 * which starts where its creator says, 0 by default); in deployment it is the wall clock read once
 * at start and advanced by a monotonic timer ({@code SystemClock}), so a clock step of the host
 * does not fire timeouts.
 */
@FunctionalInterface
public interface Clock {

    /** The current time in milliseconds. */
    long nowMillis();
}
