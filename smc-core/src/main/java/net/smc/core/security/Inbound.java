package net.smc.core.security;

import java.util.Arrays;
import net.smc.core.security.Unwrapped.ControlEvent;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The receiving half of a {@link SecureEndpoint}: every check a datagram must pass, in order, and
 * only then the state it changes. Checks that prove who sent a message (signatures, MACs) come
 * before the checks that classify it (time, counter), so that a reason counted is a reason the
 * sender really gave, not one a forger chose.
 */
final class Inbound {
    private static final Logger LOG = LoggerFactory.getLogger(Inbound.class);

    private final SecureEndpoint e;

    Inbound(SecureEndpoint endpoint) {
        this.e = endpoint;
    }

    Unwrapped unwrap(byte[] datagram) {
        long now = e.clock.nowMillis();
        Frame frame;
        try {
            frame = FrameCodec.read(datagram, e.referenceCounter());
        } catch (Malformed m) {
            return reject(Rejection.MALFORMED, null, m.getMessage());
        }
        try {
            if (frame instanceof Frame.Signed s) {
                return signed(s, now);
            }
            if (frame instanceof Frame.Hello h) {
                return hello(h, now);
            }
            Frame.Keyed k = (Frame.Keyed) frame;
            return switch (k.kind()) {
                case FrameCodec.PAIR_MAC -> pairMac(k, now);
                case FrameCodec.TEAM_MAC -> teamMac(k, now);
                default -> teamKey(k, now);
            };
        } catch (Malformed m) {
            return reject(Rejection.MALFORMED, null, m.getMessage());
        }
    }

    private Unwrapped signed(Frame.Signed s, long now) {
        Unwrapped refused = checkSigned(FrameCodec.SIGNED, s.credential(), s.datagram(), s.signedLength(), s, now);
        if (refused != null) {
            return refused;
        }
        accept(s.credential(), s, now);
        e.stats.delivered++;
        return new Unwrapped.Delivered(s.credential().vehicleId(), Protection.SIGNED,
                Arrays.copyOfRange(s.datagram(), s.payloadStart(), s.signedLength()));
    }

    /**
     * A HELLO: after the signed checks, it must be for this vehicle and newer than the last HELLO
     * taken from the sender. A session is bound to fresh values from both sides: keys are derived
     * only from a HELLO that echoes this side's current key for the pair, which proves the HELLO was
     * made after that key was (a recorded HELLO replayed to a restarted vehicle echoes a key that
     * vehicle no longer has). Any other HELLO commits nothing but the peer's offered key and is
     * answered with this side's key ({@link ControlEvent#HANDSHAKE_OFFERED}). A HELLO goes back when
     * its echo is not this side's current key, when it has just agreed new keys (so the peer, which
     * may not yet have seen this side's key echoed, can agree too), or when none went to the peer
     * within the retry interval (the peer retries: it lost the HELLO that would have let it agree).
     */
    private Unwrapped hello(Frame.Hello h, long now) throws Malformed {
        String peer = h.credential().vehicleId();
        String who = "handshake from '" + peer + "'";
        Unwrapped refused = checkSigned(FrameCodec.HELLO, h.credential(), h.datagram(), h.signedLength(), h, now);
        if (refused != null) {
            return refused;
        }
        if (!h.recipient().equals(e.id())) {
            return reject(Rejection.NOT_FOR_ME, peer, who + " is addressed to '" + h.recipient() + "', not to '" + e.id() + "'");
        }
        PeerState known = e.peers.get(peer);
        if (known != null && h.counter() <= known.lastHelloCounter) {
            return reject(Rejection.REPLAY, peer, who + ": counter " + h.counter()
                    + " is not after the newest handshake taken from it (" + known.lastHelloCounter + ")");
        }
        Ephemeral mine = known != null && known.ephemeral != null ? known.ephemeral : Ephemeral.generate(e.random());
        boolean echoed = Arrays.equals(h.echo(), mine.publicBytes());
        boolean newKey = echoed && (known == null || known.session == null || !Arrays.equals(known.session.peerEphemeral, h.ephemeral()));
        PairKeys keys = newKey
                ? PairKeys.derive(mine.agree(h.ephemeral()), e.id(), mine.publicBytes(), peer, h.ephemeral())
                : null;
        // every check has passed: from here on, commit
        PeerState p = accept(h.credential(), h, now);
        p.ephemeral = mine;
        p.peerEphemeral = h.ephemeral();
        p.lastHelloCounter = h.counter();
        ControlEvent event;
        if (keys != null) {
            p.session = new Session(keys, h.ephemeral(), e.settings.replayWindow());
            e.stats.keysAgreed++;
            event = ControlEvent.KEYS_AGREED;
        } else if (echoed) {
            e.stats.hellosRepeated++;
            event = ControlEvent.HANDSHAKE_REPEATED;
        } else {
            e.stats.hellosOffered++;
            event = ControlEvent.HANDSHAKE_OFFERED;
        }
        boolean answeredLately = p.helloSentMillis != PeerState.NEVER && now - p.helloSentMillis < e.settings.handshakeRetryMillis();
        byte[] reply = null;
        if (!echoed || keys != null || !answeredLately) {
            p.helloSentMillis = now;
            reply = e.helloDatagram(peer, p);
        }
        return new Unwrapped.Control(peer, event, reply);
    }

    private Unwrapped pairMac(Frame.Keyed k, long now) {
        if (k.sender().equals(e.id())) {
            return reject(Rejection.NOT_FOR_ME, k.sender(), describe(k) + ": claims this endpoint's own id; a reflection");
        }
        Session session = sessionOf(k);
        if (session == null) {
            return reject(Rejection.UNKNOWN_SENDER, k.sender(), describe(k) + ": no session with this sender; it must shake hands first");
        }
        if (!session.receiveMac.verify(k.counter(), k.datagram(), k.bodyEnd())) {
            return reject(Rejection.BAD_MAC, k.sender(), describe(k) + ": the MAC does not verify under the session key");
        }
        Unwrapped refused = checkPeerAndTime(k, session.window, now);
        if (refused != null) {
            return refused;
        }
        session.window.mark(k.counter(), k.timestampMillis());
        e.stats.delivered++;
        return new Unwrapped.Delivered(k.sender(), Protection.PAIR_MAC, Arrays.copyOfRange(k.datagram(), k.bodyStart(), k.bodyEnd()));
    }

    private Unwrapped teamMac(Frame.Keyed k, long now) {
        TeamKey team = e.team;
        if (team == null || team.id != k.teamId()) {
            return reject(Rejection.NO_TEAM_KEY, k.sender(), describe(k) + ": under team key " + Integer.toHexString(k.teamId()) + ", but '"
                    + e.id() + "' holds " + (team == null ? "no team key" : "team key " + Integer.toHexString(team.id)));
        }
        if (!team.mac.verify(k.counter(), k.datagram(), k.bodyEnd())) {
            return reject(Rejection.BAD_MAC, k.sender(), describe(k) + ": the MAC does not verify under the team key");
        }
        if (k.sender().equals(e.id())) {
            return reject(Rejection.NOT_FOR_ME, k.sender(), describe(k) + ": claims this endpoint's own id; a reflection");
        }
        ReplayWindow window = team.windows.get(k.sender());
        Unwrapped refused = checkTime(k, window, now);
        if (refused != null) {
            return refused;
        }
        if (window == null) {
            pruneTeamWindows(team, now);
            window = new ReplayWindow(e.settings.replayWindow());
            team.windows.put(k.sender(), window);
        }
        window.mark(k.counter(), k.timestampMillis());
        e.stats.delivered++;
        return new Unwrapped.Delivered(k.sender(), Protection.TEAM_MAC, Arrays.copyOfRange(k.datagram(), k.bodyStart(), k.bodyEnd()));
    }

    private Unwrapped teamKey(Frame.Keyed k, long now) {
        Session session = sessionOf(k);
        if (session == null) {
            return reject(Rejection.UNKNOWN_SENDER, k.sender(), describe(k) + ": no session with this sender to open it under");
        }
        byte[] key = Seal.open(session.receiveSeal, k.counter(), k.datagram(), k.bodyStart(), k.bodyEnd());
        if (key == null) {
            return reject(Rejection.BAD_MAC, k.sender(), describe(k) + ": the AES-GCM tag does not verify under the session key");
        }
        Unwrapped refused = checkPeerAndTime(k, session.window, now);
        if (refused != null) {
            return refused;
        }
        session.window.mark(k.counter(), k.timestampMillis());
        e.installTeamKey(key);
        e.stats.teamKeysInstalled++;
        return new Unwrapped.Control(k.sender(), ControlEvent.TEAM_KEY_INSTALLED, null);
    }

    /** The common checks of the signed kinds: reflection, credential, signature, time, counter. */
    private Unwrapped checkSigned(int kind, Credential credential, byte[] datagram, int signedLength, Frame frame, long now) {
        String sender = credential.vehicleId();
        String who = FrameCodec.kindName(kind) + " from '" + sender + "'";
        if (sender.equals(e.id())) {
            return reject(Rejection.NOT_FOR_ME, sender, who + ": carries this endpoint's own credential; a reflection");
        }
        PeerState known = e.peers.get(sender);
        CredentialStatus status = known != null && credential.equals(known.credential)
                ? e.trust.checkTimeAndMission(credential, now)
                : e.trust.verify(credential, now);
        if (status != CredentialStatus.VALID) {
            return rejectCredential(status, sender, who, credential, now);
        }
        byte[] signedBytes = FrameCodec.toBeSigned(frame.counter(), datagram, signedLength);
        if (!credential.vehicleKey().verify(signedBytes, 0, signedBytes.length, datagram, signedLength)) {
            return reject(Rejection.BAD_SIGNATURE, sender, who + ": the signature does not verify with the key of its credential");
        }
        return checkTime(frame, known == null ? null : known.signedWindow, now, sender, who);
    }

    /** The checks of a keyed kind after its MAC: the peer's credential still valid, then time and counter. */
    private Unwrapped checkPeerAndTime(Frame.Keyed k, ReplayWindow window, long now) {
        Credential credential = e.peers.get(k.sender()).credential;
        CredentialStatus status = e.trust.checkTimeAndMission(credential, now);
        if (status != CredentialStatus.VALID) {
            return rejectCredential(status, k.sender(), describe(k), credential, now);
        }
        return checkTime(k, window, now);
    }

    private Unwrapped checkTime(Frame.Keyed k, ReplayWindow window, long now) {
        return checkTime(k, window, now, k.sender(), describe(k));
    }

    /** Refuses a counter whose time is outside the freshness window, then one {@code window} has seen (a null window has seen none). */
    private Unwrapped checkTime(Frame frame, ReplayWindow window, long now, String sender, String who) {
        long ts = frame.timestampMillis();
        long w = e.settings.freshnessWindowMillis();
        if (ts < now - w || ts > now + w) {
            return reject(Rejection.STALE, sender, who + ": timestamp " + ts + " ms is " + Math.abs(now - ts) + " ms "
                    + (ts < now ? "behind" : "ahead of") + " the clock (" + now + " ms); the freshness window is " + w + " ms either way");
        }
        if (window != null && !window.isFresh(frame.counter())) {
            return reject(Rejection.REPLAY, sender, who + ": counter " + frame.counter()
                    + " was seen already, or is older than any still remembered");
        }
        return null;
    }

    private Unwrapped rejectCredential(CredentialStatus status, String sender, String who, Credential c, long now) {
        return switch (status) {
            case FOREIGN_AUTHORITY -> reject(Rejection.FOREIGN_AUTHORITY, sender, who + ": credential issued by authority "
                    + c.authority() + "; this vehicle trusts " + e.trust.authority().id());
            case BAD_SIGNATURE -> reject(Rejection.BAD_SIGNATURE, sender, who
                    + ": the authority's signature of its credential does not verify");
            case NOT_YET_VALID -> reject(Rejection.CREDENTIAL_NOT_YET_VALID, sender, who + ": credential valid from "
                    + c.notBeforeMillis() + " ms; the clock says " + now + " ms");
            case EXPIRED -> reject(Rejection.EXPIRED_CREDENTIAL, sender, who + ": credential expired at " + c.expiresMillis()
                    + " ms; the clock says " + now + " ms");
            case WRONG_MISSION -> reject(Rejection.WRONG_MISSION, sender, who + ": credential for mission '" + c.mission()
                    + "'; this vehicle trusts only '" + e.trust.mission() + "'");
            case VALID -> throw new IllegalArgumentException("a valid credential is not refused");
        };
    }

    /** Commits an authenticated signed message: the peer's record, its credential and its counter. */
    private PeerState accept(Credential credential, Frame frame, long now) {
        PeerState p = e.peerRecord(credential.vehicleId(), now);
        p.credential = credential;
        p.signedWindow.mark(frame.counter(), frame.timestampMillis());
        return p;
    }

    private Session sessionOf(Frame.Keyed k) {
        PeerState p = e.peers.get(k.sender());
        return p == null ? null : p.session;
    }

    private void pruneTeamWindows(TeamKey team, long now) {
        if (team.windows.size() >= 1024) {
            long horizon = now - e.settings.freshnessWindowMillis();
            team.windows.values().removeIf(w -> w.newestTimestampMillis() < horizon);
        }
    }

    private static String describe(Frame.Keyed k) {
        return FrameCodec.kindName(k.kind()) + " from '" + k.sender() + "'";
    }

    private Unwrapped reject(Rejection reason, String claimedSender, String detail) {
        e.stats.reject(reason);
        LOG.debug("'{}' refused a datagram ({}): {}", e.id(), reason, detail);
        return new Unwrapped.Rejected(reason, claimedSender, detail);
    }
}
