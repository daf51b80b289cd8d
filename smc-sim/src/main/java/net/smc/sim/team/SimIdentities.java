package net.smc.sim.team;

import java.security.NoSuchAlgorithmException;
import java.security.SecureRandom;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import net.smc.core.security.Claims;
import net.smc.core.security.Credential;
import net.smc.core.security.SigningIdentity;
import net.smc.core.security.SigningKey;
import net.smc.core.security.TrustAnchor;

/**
 * The keys and credentials of simulated and test vehicles: one test authority (and a foreign one for
 * rogues), keys derived from seeds so they are the same in every run.
 */
public final class SimIdentities {
    private static final Map<String, SigningIdentity> IDENTITIES = new ConcurrentHashMap<>();
    private static final SigningKey AUTHORITY = key(1);
    private static final SigningKey FOREIGN_AUTHORITY = key(2);

    private SimIdentities() {
    }

    /**
     * The key and credential of a simulated or test vehicle for a mission, issued by the test
     * authority (a foreign one for a rogue). Made once per vehicle id and JVM: Ed25519 is slow and
     * they change no outcome.
     */
    public static SigningIdentity identity(SimVehicle v, String missionName) {
        return IDENTITIES.computeIfAbsent((v.rogue() ? "rogue:" : "") + v.id() + "@" + missionName, k -> {
            SigningKey key = key(k.hashCode() * 7919L + 3);
            SigningKey issuer = v.rogue() ? FOREIGN_AUTHORITY : AUTHORITY;
            return new SigningIdentity(key, Credential.issue(new Claims(v.id(), key.verificationKey(), missionName, 0,
                    Long.MAX_VALUE / 2), issuer));
        });
    }

    private static SigningKey key(long seed) {
        return SigningKey.generate(seeded(seed));
    }

    /** A SecureRandom that gives the same bytes for the same seed: for keys of simulated and test vehicles only. */
    public static SecureRandom seeded(long seed) {
        try {
            SecureRandom random = SecureRandom.getInstance("SHA1PRNG");
            random.setSeed(seed);
            return random;
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("SHA1PRNG is missing from this JDK", e);
        }
    }

    /** What the vehicles of {@link #identity} trust: the test authority, for that mission. */
    public static TrustAnchor trust(String missionName) {
        return new TrustAnchor(AUTHORITY.verificationKey(), missionName);
    }
}
