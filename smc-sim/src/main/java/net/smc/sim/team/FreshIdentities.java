package net.smc.sim.team;

import java.security.SecureRandom;
import java.util.Map;
import java.util.Objects;
import java.util.concurrent.ConcurrentHashMap;

import net.smc.core.security.Claims;
import net.smc.core.security.Credential;
import net.smc.core.security.SigningIdentity;
import net.smc.core.security.SigningKey;
import net.smc.core.security.TrustAnchor;

/**
 * Keys and credentials made afresh for one team on the real network: a mission authority of its
 * own, and for each vehicle an Ed25519 key from {@link SecureRandom} with a credential that
 * authority signs for the mission, valid over the times given (on the clock the team's cells
 * read). Nothing is shared with another team or run, as with keys made by {@code smc keys}.
 */
public final class FreshIdentities {
    private final SecureRandom random = new SecureRandom();
    private final SigningKey authority = SigningKey.generate(random);
    private final String mission;
    private final long notBeforeMillis;
    private final long expiresMillis;
    private final Map<String, SigningIdentity> made = new ConcurrentHashMap<>();

    /**
     * @throws IllegalArgumentException when the validity is empty
     */
    public FreshIdentities(String mission, long notBeforeMillis, long expiresMillis) {
        if (expiresMillis <= notBeforeMillis) {
            throw new IllegalArgumentException("credentials would expire at " + expiresMillis
                    + " ms, not after they become valid at " + notBeforeMillis + " ms");
        }
        this.mission = Objects.requireNonNull(mission, "mission");
        this.notBeforeMillis = notBeforeMillis;
        this.expiresMillis = expiresMillis;
    }

    /** The key and credential of a vehicle, made at the first call for it. */
    public SigningIdentity identity(String vehicle) {
        return made.computeIfAbsent(vehicle, v -> {
            SigningKey key = SigningKey.generate(random);
            return new SigningIdentity(key, Credential.issue(new Claims(v, key.verificationKey(), mission,
                    notBeforeMillis, expiresMillis), authority));
        });
    }

    /** What the team's vehicles trust: this authority, for this mission. */
    public TrustAnchor trust() {
        return new TrustAnchor(authority.verificationKey(), mission);
    }
}
