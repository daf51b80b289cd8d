package net.smc.core.security;

/**
 * What two vehicles share after a handshake: a MAC per direction, a sealing key per direction, and
 * the receiver's memory of the peer's counters under this session.
 */
final class Session {
    final TruncatedMac sendMac;
    final TruncatedMac receiveMac;
    final byte[] sendSeal;
    final byte[] receiveSeal;
    final ReplayWindow window;

    Session(PairKeys keys, int replayWindow) {
        this.sendMac = new TruncatedMac(keys.sendMac());
        this.receiveMac = new TruncatedMac(keys.receiveMac());
        this.sendSeal = keys.sendSeal();
        this.receiveSeal = keys.receiveSeal();
        this.window = new ReplayWindow(replayWindow);
    }
}
