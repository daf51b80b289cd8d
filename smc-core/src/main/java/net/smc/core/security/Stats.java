package net.smc.core.security;

import java.util.EnumMap;
import java.util.Map;

/** The live counters behind {@link SecurityCounters}; bumped on the endpoint's one thread. */
final class Stats {
    long signedWrapped;
    long pairWrapped;
    long teamWrapped;
    long hellosSent;
    long keysAgreed;
    long hellosRepeated;
    long hellosOffered;
    long teamKeysSent;
    long teamKeysInstalled;
    long delivered;
    private final long[] rejected = new long[Rejection.values().length];

    void reject(Rejection reason) {
        rejected[reason.ordinal()]++;
    }

    SecurityCounters snapshot() {
        Map<Rejection, Long> byReason = new EnumMap<>(Rejection.class);
        for (Rejection r : Rejection.values()) {
            byReason.put(r, rejected[r.ordinal()]);
        }
        return new SecurityCounters(signedWrapped, pairWrapped, teamWrapped, hellosSent, keysAgreed, hellosRepeated,
                hellosOffered, teamKeysSent, teamKeysInstalled, delivered, byReason);
    }
}
