package net.smc.core.security;

import java.nio.charset.StandardCharsets;
import java.util.Arrays;

/**
 * The four keys of one session, one per direction and purpose, so that a MAC one side made can
 * never be reflected back as the other's: HMAC keys for MAC'd messages and AES-256 keys for the
 * team key sent under the session.
 *
 * <p>Derived with HKDF-SHA256: the X25519 shared secret as input, both ephemeral public values as
 * salt, and {@code "smc-pair-v1"} and both vehicle ids (each length-prefixed) as info; 128 bytes,
 * cut in the order of the fields. "First" is the vehicle whose id sorts first ({@link String#compareTo}),
 * so both sides derive the same keys whoever spoke first: the handshake has no initiator.
 */
record PairKeys(byte[] sendMac, byte[] receiveMac, byte[] sendSeal, byte[] receiveSeal) {
    private static final byte[] LABEL = "smc-pair-v1".getBytes(StandardCharsets.US_ASCII);

    /** The keys as the vehicle {@code myId} sees them. */
    static PairKeys derive(byte[] shared, String myId, byte[] myEphemeral, String peerId, byte[] peerEphemeral) {
        boolean first = myId.compareTo(peerId) < 0;
        byte[] salt = first ? concat(myEphemeral, peerEphemeral) : concat(peerEphemeral, myEphemeral);
        byte[] i = (first ? myId : peerId).getBytes(StandardCharsets.UTF_8);
        byte[] r = (first ? peerId : myId).getBytes(StandardCharsets.UTF_8);
        byte[] info = concat(LABEL, new byte[] {(byte) i.length}, i, new byte[] {(byte) r.length}, r);
        byte[] okm = Hkdf.derive(salt, shared, info, 128);
        byte[] macIr = Arrays.copyOfRange(okm, 0, 32);
        byte[] macRi = Arrays.copyOfRange(okm, 32, 64);
        byte[] sealIr = Arrays.copyOfRange(okm, 64, 96);
        byte[] sealRi = Arrays.copyOfRange(okm, 96, 128);
        return first ? new PairKeys(macIr, macRi, sealIr, sealRi) : new PairKeys(macRi, macIr, sealRi, sealIr);
    }

    static byte[] concat(byte[]... parts) {
        int n = 0;
        for (byte[] p : parts) {
            n += p.length;
        }
        byte[] out = new byte[n];
        int at = 0;
        for (byte[] p : parts) {
            System.arraycopy(p, 0, out, at, p.length);
            at += p.length;
        }
        return out;
    }
}
