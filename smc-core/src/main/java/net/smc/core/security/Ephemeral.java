package net.smc.core.security;

import java.security.SecureRandom;

import org.bouncycastle.math.ec.rfc7748.X25519;

/**
 * One side's X25519 key pair for one handshake, thrown away when the session keys are derived, so
 * that a key stolen later cannot open earlier sessions (forward secrecy). Bouncy Castle's RFC 7748
 * code does the arithmetic (the JDK 17's provider gives the same values about ten times slower);
 * the private scalar is the next 32 bytes of the random source, as the JDK draws it.
 */
final class Ephemeral {
    static final int BYTES = 32;

    private final byte[] privateScalar;
    private final byte[] publicBytes;

    private Ephemeral(byte[] privateScalar) {
        this.privateScalar = privateScalar;
        this.publicBytes = new byte[BYTES];
        X25519.generatePublicKey(privateScalar, 0, publicBytes, 0);
    }

    static Ephemeral generate(SecureRandom random) {
        byte[] scalar = new byte[BYTES];
        random.nextBytes(scalar);
        return new Ephemeral(scalar);
    }

    /** The 32-byte public value (a copy). */
    byte[] publicBytes() {
        return publicBytes.clone();
    }

    /**
     * The shared secret with the peer's 32-byte public value.
     *
     * @throws Malformed when the peer's value is not 32 bytes, or is a point of small order (the
     *                   secret would be all zeros, predictable)
     */
    byte[] agree(byte[] peerPublic) throws Malformed {
        if (peerPublic.length != BYTES) {
            throw new Malformed("ephemeral key refused: " + peerPublic.length + " bytes, not " + BYTES);
        }
        byte[] secret = new byte[BYTES];
        if (!X25519.calculateAgreement(privateScalar, 0, peerPublic, 0, secret, 0)) {
            throw new Malformed("ephemeral key refused: a point of small order (the shared secret would be zero)");
        }
        return secret;
    }
}
