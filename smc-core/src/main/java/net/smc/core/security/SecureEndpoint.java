package net.smc.core.security;

import java.nio.charset.StandardCharsets;
import java.security.SecureRandom;
import java.util.HashMap;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import net.smc.core.transport.Clock;
import net.smc.core.transport.Transport;

/**
 * Start here: one vehicle's authentication layer, sans-IO. It wraps outgoing payloads in a
 * protected envelope and unwraps incoming datagrams into an authenticated sender and payload, or a
 * counted refusal; it never sends, reads a clock of its own or starts a thread. Payloads are opaque
 * bytes, so it composes with any message codec; {@link SecureTransport} puts it under a cell.
 *
 * <p>Three protections (see <a href="doc-files/security.md">the security design note</a>):
 * <ul>
 *   <li>{@link #wrapSigned}: an Ed25519 signature with the sender's credential attached, checkable
 *       by anyone who trusts the authority, with no earlier contact: discovery, first replies;</li>
 *   <li>{@link #wrapFor}: an HMAC under the key of a session that a signed X25519 handshake
 *       ({@link #startHandshake}) sets up: every unicast after that, heartbeats included;</li>
 *   <li>{@link #wrapTeam}: an HMAC under the team key a commander hands out ({@link #wrapTeamKey}).</li>
 * </ul>
 * Every envelope carries the sender's counter, which follows its clock; a receiver refuses what is
 * stale or repeated. A refused datagram is counted under its {@link Rejection} and changes nothing else.
 *
 * <pre>{@code
 * SecureEndpoint a = SecureEndpoint.builder(identityA, trust, clock).build();
 * byte[] hello = a.startHandshake("uav-2");               // send to uav-2
 * Unwrapped u = b.unwrap(hello);                          // Control(HANDSHAKE_OFFERED) with b's value for uav-1
 * u = a.unwrap(((Unwrapped.Control) u).reply());          // Control(KEYS_AGREED), echoing b's value
 * u = b.unwrap(((Unwrapped.Control) u).reply());          // Control(KEYS_AGREED), a confirmation
 * a.unwrap(((Unwrapped.Control) u).reply());              // Control(HANDSHAKE_REPEATED), no reply
 * b.unwrap(a.wrapFor("uav-2", heartbeat));                // Delivered("uav-1", PAIR_MAC, heartbeat)
 * }</pre>
 *
 * <p>Not thread-safe: it belongs to its cell's thread, as everything a cell owns does.
 */
public final class SecureEndpoint {
    /** A counter follows the clock shifted left by this many bits (see {@link #nextCounter}). */
    static final int COUNTER_SHIFT = 20;
    private static final int PRUNE_ABOVE = 1024;

    final SigningIdentity identity;
    final TrustAnchor trust;
    final Clock clock;
    final SecuritySettings settings;
    final Stats stats = new Stats();
    final Map<String, PeerState> peers = new HashMap<>();
    final byte[] idBytes;
    TeamKey team;
    private final SecureRandom random;
    private final byte[] credentialBytes;
    private final Inbound inbound;
    private long counter = Long.MIN_VALUE;

    private SecureEndpoint(Builder b) {
        this.identity = b.identity;
        this.trust = b.trust;
        this.clock = b.clock;
        this.random = b.random != null ? b.random : new SecureRandom();
        this.settings = b.settings;
        this.credentialBytes = identity.credential().encode();
        this.idBytes = identity.id().getBytes(StandardCharsets.UTF_8);
        this.inbound = new Inbound(this);
    }

    /** An endpoint for {@code identity} that trusts {@code trust} and reads time from {@code clock}. */
    public static Builder builder(SigningIdentity identity, TrustAnchor trust, Clock clock) {
        return new Builder(identity, trust, clock);
    }

    /** This vehicle's id. */
    public String id() {
        return identity.id();
    }

    /** The envelope bytes {@code protection} adds to a payload from this endpoint. */
    public int overhead(Protection protection) {
        return switch (protection) {
            case SIGNED -> FrameCodec.signedOverhead(credentialBytes.length);
            case PAIR_MAC -> FrameCodec.pairOverhead(idBytes.length);
            case TEAM_MAC -> FrameCodec.teamOverhead(idBytes.length);
        };
    }

    /** The largest payload that still fits one datagram under {@code protection}. */
    public int maxPayload(Protection protection) {
        return Transport.MAX_DATAGRAM_BYTES - overhead(protection);
    }

    /**
     * Signs {@code payload}, attaching this vehicle's credential.
     *
     * @throws PayloadTooLargeException when the datagram would exceed {@link Transport#MAX_DATAGRAM_BYTES}
     */
    public byte[] wrapSigned(byte[] payload) {
        fits(Protection.SIGNED, payload);
        long ctr = nextCounter();
        byte[] datagram = FrameCodec.signed(credentialBytes, ctr, payload);
        sign(ctr, datagram);
        stats.signedWrapped++;
        return datagram;
    }

    /**
     * MACs {@code payload} for {@code peer} under the session with it.
     *
     * @throws IllegalStateException     when there is no session with {@code peer}
     * @throws PayloadTooLargeException  when the datagram would exceed {@link Transport#MAX_DATAGRAM_BYTES}
     */
    public byte[] wrapFor(String peer, byte[] payload) {
        Session session = sessionWith(peer, "wrap a payload for it");
        fits(Protection.PAIR_MAC, payload);
        long ctr = nextCounter();
        byte[] datagram = FrameCodec.keyed(FrameCodec.PAIR_MAC, 0, idBytes, ctr, payload, FrameCodec.MAC);
        session.sendMac.sign(ctr, datagram, datagram.length - FrameCodec.MAC);
        stats.pairWrapped++;
        return datagram;
    }

    /**
     * MACs {@code payload} under the team key, for a broadcast to the team.
     *
     * @throws IllegalStateException    when this endpoint holds no team key
     * @throws PayloadTooLargeException when the datagram would exceed {@link Transport#MAX_DATAGRAM_BYTES}
     */
    public byte[] wrapTeam(byte[] payload) {
        if (team == null) {
            throw new IllegalStateException("'" + id() + "' holds no team key: a commander makes one (newTeamKey) and sends it to members (wrapTeamKey)");
        }
        fits(Protection.TEAM_MAC, payload);
        long ctr = nextCounter();
        byte[] datagram = FrameCodec.keyed(FrameCodec.TEAM_MAC, team.id, idBytes, ctr, payload, FrameCodec.MAC);
        team.mac.sign(ctr, datagram, datagram.length - FrameCodec.MAC);
        stats.teamWrapped++;
        return datagram;
    }

    /**
     * A handshake for {@code peer}, to be sent to it: a signed HELLO offering this side's X25519 key
     * for the pair (made now if there is none; a retry offers the same one) and echoing the peer's
     * key as last seen. The peer answers when it has not yet seen this side's key; each side derives
     * the session keys on taking a HELLO that echoes its own key and brings the other's
     * ({@link Unwrapped.ControlEvent#KEYS_AGREED}). Works for a peer not yet authenticated too (say
     * one that sent a MAC'd message this endpoint forgot the key of): the HELLO proves who sends it.
     */
    public byte[] startHandshake(String peer) {
        if (WireNames.checkPeerId(peer).equals(id())) {
            throw new IllegalArgumentException("'" + id() + "' cannot shake hands with itself");
        }
        PeerState p = peerRecord(peer, clock.nowMillis());
        if (p.ephemeral == null) {
            p.ephemeral = Ephemeral.generate(random);
        }
        p.helloSentMillis = clock.nowMillis();
        return helloDatagram(peer, p);
    }

    /**
     * Whether a handshake with {@code peer} is due: there is no session, and no HELLO went to it in
     * the last {@link SecuritySettings#handshakeRetryMillis()}.
     */
    public boolean needsHandshake(String peer) {
        PeerState p = peers.get(peer);
        return p == null || p.session == null
                && (p.helloSentMillis == PeerState.NEVER || clock.nowMillis() - p.helloSentMillis >= settings.handshakeRetryMillis());
    }

    /** Whether there is a session with {@code peer}. */
    public boolean hasSession(String peer) {
        PeerState p = peers.get(peer);
        return p != null && p.session != null;
    }

    /**
     * Forgets the session with {@code peer} and both keys it came from (the peer failed, or left the
     * team); a later handshake starts afresh. Its counters are kept, so nothing old replays.
     */
    public void forget(String peer) {
        PeerState p = peers.get(peer);
        if (p != null) {
            p.session = null;
            p.ephemeral = null;
            p.peerEphemeral = null;
            p.helloSentMillis = PeerState.NEVER;
        }
    }

    /** The last verified credential of {@code peer}, if it has authenticated itself. */
    public Optional<Credential> credentialOf(String peer) {
        PeerState p = peers.get(peer);
        return p == null ? Optional.empty() : Optional.ofNullable(p.credential);
    }

    /** Makes a new random team key and uses it from now on (a commander does this, once per team). */
    public void newTeamKey() {
        byte[] key = new byte[FrameCodec.TEAM_KEY_BYTES];
        random.nextBytes(key);
        team = new TeamKey(key);
    }

    /** Whether this endpoint holds a team key. */
    public boolean hasTeamKey() {
        return team != null;
    }

    /**
     * The team key sealed (AES-256-GCM) under the session with {@code peer}, to be sent to it, for
     * instance with its role assignment.
     *
     * @throws IllegalStateException when there is no team key, or no session with {@code peer}
     */
    public byte[] wrapTeamKey(String peer) {
        Session session = sessionWith(peer, "send it the team key");
        if (team == null) {
            throw new IllegalStateException("'" + id() + "' holds no team key to send to '" + peer + "'; make one first (newTeamKey)");
        }
        long ctr = nextCounter();
        int aadLength = FrameCodec.keyedHeaderBytes(FrameCodec.TEAM_KEY, idBytes.length);
        byte[] header = FrameCodec.keyed(FrameCodec.TEAM_KEY, 0, idBytes, ctr, new byte[0], 0);
        byte[] sealed = Seal.seal(session.sendSeal, ctr, header, aadLength, team.key);
        byte[] datagram = PairKeys.concat(header, sealed);
        stats.teamKeysSent++;
        return datagram;
    }

    /**
     * Checks a datagram and answers what it is: an authenticated payload, a handshake step (with a
     * reply to send, perhaps), or a refusal. Never throws for any input; a refusal is counted and
     * changes no state.
     */
    public Unwrapped unwrap(byte[] datagram) {
        return inbound.unwrap(Objects.requireNonNull(datagram, "datagram"));
    }

    /** What this endpoint has done so far. */
    public SecurityCounters counters() {
        return stats.snapshot();
    }

    SecureRandom random() {
        return random;
    }

    /** Makes {@code key} the team key; the same key again keeps what was remembered of counters under it. */
    void installTeamKey(byte[] key) {
        if (team == null || !java.util.Arrays.equals(team.key, key)) {
            team = new TeamKey(key);
        }
    }

    /**
     * The next counter: one more than the last, but never behind the clock scaled by 2^20. So a
     * vehicle that restarts (and forgets its counter) still counts above what it sent before, as
     * long as it sent fewer than about a million datagrams per millisecond.
     */
    long nextCounter() {
        counter = Math.max(counter + 1, clock.nowMillis() << COUNTER_SHIFT);
        return counter;
    }

    /** Where a receiver looks for a sender's counter: its own clock, shifted as a counter is. */
    long referenceCounter() {
        return clock.nowMillis() << COUNTER_SHIFT;
    }

    /** A signed HELLO to {@code peer}: this side's key for the pair, and the peer's as last seen. */
    byte[] helloDatagram(String peer, PeerState p) {
        long ctr = nextCounter();
        byte[] datagram = FrameCodec.hello(credentialBytes, ctr, peer.getBytes(StandardCharsets.UTF_8), p.ephemeral.publicBytes(),
                p.peerEphemeral);
        sign(ctr, datagram);
        stats.hellosSent++;
        return datagram;
    }

    /**
     * The record of {@code peer}, made if new. When there are many, first forgets the idle ones
     * (no session, no handshake) whose newest signed message is older than the freshness window
     * (whatever they could replay would be refused as stale anyway), and those that never
     * authenticated and have no session (handshakes started towards a mere claim).
     */
    PeerState peerRecord(String peer, long nowMillis) {
        PeerState p = peers.get(peer);
        if (p == null) {
            if (peers.size() >= PRUNE_ABOVE) {
                long horizon = nowMillis - settings.freshnessWindowMillis();
                peers.values().removeIf(q -> q.idle() && q.signedWindow.newestTimestampMillis() < horizon
                        || q.credential == null && q.session == null);
            }
            p = new PeerState(settings.replayWindow());
            peers.put(peer, p);
        }
        return p;
    }

    /** Signs the full {@code counter} and the datagram before its signature; writes the signature at its end. */
    private void sign(long counter, byte[] datagram) {
        int n = datagram.length - FrameCodec.SIG;
        System.arraycopy(identity.key().sign(FrameCodec.toBeSigned(counter, datagram, n)), 0, datagram, n, FrameCodec.SIG);
    }

    private Session sessionWith(String peer, String purpose) {
        PeerState p = peers.get(Objects.requireNonNull(peer, "peer"));
        if (p == null || p.session == null) {
            throw new IllegalStateException("'" + id() + "' has no session with '" + peer + "' to " + purpose
                    + "; start a handshake first (startHandshake)");
        }
        return p.session;
    }

    private void fits(Protection protection, byte[] payload) {
        int overhead = overhead(protection);
        if (payload.length + overhead > Transport.MAX_DATAGRAM_BYTES) {
            throw new PayloadTooLargeException(protection, payload.length, overhead, Transport.MAX_DATAGRAM_BYTES - overhead);
        }
    }

    /** Collects what an endpoint is given; a clock, an identity and a trust anchor are required. */
    public static final class Builder {
        private final SigningIdentity identity;
        private final TrustAnchor trust;
        private final Clock clock;
        private SecureRandom random;
        private SecuritySettings settings = SecuritySettings.DEFAULTS;

        private Builder(SigningIdentity identity, TrustAnchor trust, Clock clock) {
            this.identity = Objects.requireNonNull(identity, "identity");
            this.trust = Objects.requireNonNull(trust, "trust");
            this.clock = Objects.requireNonNull(clock, "clock");
        }

        /** Where ephemeral and team keys come from; a fresh {@link SecureRandom} unless given (a seeded one replays a simulation). */
        public Builder random(SecureRandom random) {
            this.random = Objects.requireNonNull(random, "random");
            return this;
        }

        /** The settings; {@link SecuritySettings#DEFAULTS} unless given. */
        public Builder settings(SecuritySettings settings) {
            this.settings = Objects.requireNonNull(settings, "settings");
            return this;
        }

        public SecureEndpoint build() {
            return new SecureEndpoint(this);
        }
    }
}
