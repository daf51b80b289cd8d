package net.smc.core.security;

/**
 * What two vehicles share after a handshake: a MAC per direction, a sealing key per direction, and
 * the receiver's memory of the peer's counters under this session, and the peer's X25519 value the
 * session was derived from (a HELLO bringing another value agrees a new session).
 */
final class Session {
    final TruncatedMac sendMac;
    final TruncatedMac receiveMac;
    final byte[] sendSeal;
    final byte[] receiveSeal;
    final ReplayWindow window;
    final byte[] peerEphemeral;

    Session(PairKeys keys, byte[] peerEphemeral, int replayWindow) {
        this.peerEphemeral = peerEphemeral.clone();
        this.sendMac = new TruncatedMac(keys.sendMac());
        this.receiveMac = new TruncatedMac(keys.receiveMac());
        this.sendSeal = keys.sendSeal();
        this.receiveSeal = keys.receiveSeal();
        this.window = new ReplayWindow(replayWindow);
    }
}
