package net.smc.core.transport.sim;

import java.util.HashMap;
import java.util.Map;
import java.util.Objects;
import java.util.random.RandomGenerator;

import net.smc.core.transport.Address;

/**
 * The link profiles of an {@link InMemoryNetwork} (a default plus directed overrides) and the
 * random draws they call for. The draws for one copy are made in a fixed order (loss, then delay,
 * then re-order, then duplication, then the duplicate's delay and re-order), and only those a
 * profile can need, so one seed and one sequence of sends give one sequence of outcomes.
 */
final class Links {
    private record Link(Address from, Address to) {
    }

    private final RandomGenerator random;
    private final Map<Link, LinkProfile> overrides = new HashMap<>();   // looked up only, never iterated
    private LinkProfile defaultProfile = LinkProfile.DEFAULT;

    Links(RandomGenerator random) {
        this.random = Objects.requireNonNull(random, "random");
    }

    void setDefault(LinkProfile profile) {
        defaultProfile = Objects.requireNonNull(profile, "profile");
    }

    void set(Address from, Address to, LinkProfile profile) {
        overrides.put(new Link(Objects.requireNonNull(from, "from"), Objects.requireNonNull(to, "to")),
                Objects.requireNonNull(profile, "profile"));
    }

    void clearOverrides() {
        overrides.clear();
    }

    LinkProfile profile(Address from, Address to) {
        return overrides.isEmpty() ? defaultProfile : overrides.getOrDefault(new Link(from, to), defaultProfile);
    }

    boolean lost(LinkProfile p) {
        return p.lossProbability() > 0 && random.nextDouble() < p.lossProbability();
    }

    boolean duplicated(LinkProfile p) {
        return p.duplicateProbability() > 0 && random.nextDouble() < p.duplicateProbability();
    }

    /** The delay of one copy in milliseconds: latency, jitter, and the re-order hold-back if it strikes. */
    long delayMillis(LinkProfile p) {
        long delay = p.latencyMillis();
        if (p.jitterMillis() > 0) {
            delay += random.nextLong(p.jitterMillis() + 1);
        }
        if (p.reorderProbability() > 0 && random.nextDouble() < p.reorderProbability()) {
            delay += p.reorderDelayMillis();
        }
        return delay;
    }
}
