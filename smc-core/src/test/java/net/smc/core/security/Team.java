package net.smc.core.security;

import java.security.NoSuchAlgorithmException;
import java.security.SecureRandom;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import net.smc.core.transport.Clock;

/**
 * A test team: one mission authority, vehicles with credentials valid around {@link #T0}, endpoints
 * on one settable clock, all keys from one seed.
 */
final class Team {
    static final long T0 = 1_700_000_000_000L;
    static final long HOUR = 3_600_000L;
    static final String MISSION = "rescue";

    final SecureRandom random;
    final SigningKey authority;
    final TrustAnchor trust;
    final SettableClock clock = new SettableClock(T0);

    Team(long seed) {
        this.random = seeded(seed);
        this.authority = SigningKey.generate(random);
        this.trust = new TrustAnchor(authority.verificationKey(), MISSION);
    }

    static SecureRandom seeded(long seed) {
        try {
            SecureRandom random = SecureRandom.getInstance("SHA1PRNG");
            random.setSeed(seed);
            return random;
        } catch (NoSuchAlgorithmException e) {
            throw new AssertionError(e);
        }
    }

    /** A vehicle with a new key and a credential for the mission, valid from an hour before T0 to a day after. */
    SigningIdentity identity(String id) {
        return identity(id, T0 - HOUR, T0 + 24 * HOUR, MISSION, authority);
    }

    SigningIdentity identity(String id, long notBefore, long expires, String mission, SigningKey issuer) {
        SigningKey key = SigningKey.generate(random);
        return new SigningIdentity(key, Credential.issue(new Claims(id, key.verificationKey(), mission, notBefore, expires), issuer));
    }

    SecureEndpoint endpoint(String id) {
        return endpoint(identity(id));
    }

    SecureEndpoint endpoint(SigningIdentity identity) {
        return endpoint(identity, clock);
    }

    SecureEndpoint endpoint(SigningIdentity identity, Clock clock) {
        return SecureEndpoint.builder(identity, trust, clock).random(random).build();
    }

    /** Runs a handshake between two endpoints to completion, delivering every reply; answers the datagrams exchanged. */
    static int shakeHands(SecureEndpoint a, SecureEndpoint b) {
        byte[] next = a.startHandshake(b.id());
        SecureEndpoint to = b;
        int exchanged = 0;
        while (next != null) {
            exchanged++;
            Unwrapped u = to.unwrap(next);
            if (!(u instanceof Unwrapped.Control c)) {
                throw new AssertionError("handshake step refused: " + u);
            }
            next = c.reply();
            to = to == a ? b : a;
        }
        return exchanged;
    }

    /**
     * A description of everything an endpoint holds that a datagram could change, bar the refusal
     * counters: sessions and keys by identity, counters remembered, team key. Equal before and after
     * a refused datagram means the refusal changed nothing.
     */
    static String state(SecureEndpoint e) {
        List<String> parts = new ArrayList<>();
        for (Map.Entry<String, PeerState> entry : new java.util.TreeMap<>(e.peers).entrySet()) {
            PeerState p = entry.getValue();
            parts.add(entry.getKey() + "{cred=" + p.credential + ", signed=" + p.signedWindow
                    + ", eph=" + System.identityHashCode(p.ephemeral) + ", peerEph=" + java.util.Arrays.toString(p.peerEphemeral)
                    + ", lastHello=" + p.lastHelloCounter + ", helloSent=" + p.helloSentMillis
                    + ", session=" + (p.session == null ? "none" : System.identityHashCode(p.session) + "/" + p.session.window) + "}");
        }
        parts.add("team=" + (e.team == null ? "none" : e.team.id + "/" + new java.util.TreeMap<>(e.team.windows)));
        SecurityCounters c = e.counters();
        parts.add("delivered=" + c.delivered() + ", agreed=" + c.keysAgreed() + ", repeated=" + c.hellosRepeated() + ", offered=" + c.hellosOffered()
                + ", teamKeys=" + c.teamKeysInstalled());
        return String.join("\n", parts);
    }

    /** A clock the test moves. */
    static final class SettableClock implements Clock {
        private long now;

        SettableClock(long now) {
            this.now = now;
        }

        @Override
        public long nowMillis() {
            return now;
        }

        void advance(long millis) {
            now += millis;
        }

        void set(long millis) {
            now = millis;
        }
    }
}
