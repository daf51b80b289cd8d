package net.smc.core.security;

/**
 * What an endpoint knows about one vehicle: its last verified credential (so an unchanged one is
 * not verified again; null until the vehicle has authenticated itself), its signed counters, and
 * the handshake state: this side's ephemeral key for the pair, the peer's as last seen, and the
 * session derived from the two.
 */
final class PeerState {
    static final long NEVER = Long.MIN_VALUE;

    Credential credential;
    final ReplayWindow signedWindow;
    /** This side's X25519 key for the pair; kept across retries so that every HELLO offers the same one. */
    Ephemeral ephemeral;
    /** The peer's X25519 public value from its newest HELLO, or null. */
    byte[] peerEphemeral;
    /** The counter of the newest HELLO taken from the peer; an older one is out of date. */
    long lastHelloCounter = NEVER;
    /** When this side last sent the peer a HELLO. */
    long helloSentMillis = NEVER;
    Session session;

    PeerState(int replayWindow) {
        this.signedWindow = new ReplayWindow(replayWindow);
    }

    /** Whether nothing but counters is held: no session, no handshake under way. */
    boolean idle() {
        return session == null && ephemeral == null;
    }
}
