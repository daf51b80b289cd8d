package net.smc.core.security;

import java.security.GeneralSecurityException;
import java.security.KeyFactory;
import java.security.KeyPair;
import java.security.KeyPairGenerator;
import java.security.SecureRandom;
import java.security.spec.NamedParameterSpec;
import java.security.spec.X509EncodedKeySpec;
import java.util.Arrays;
import java.util.HexFormat;
import javax.crypto.KeyAgreement;

/**
 * One side's X25519 key pair for one handshake, thrown away when the session keys are derived, so
 * that a key stolen later cannot open earlier sessions (forward secrecy).
 */
final class Ephemeral {
    static final int BYTES = 32;
    private static final byte[] X509_PREFIX = HexFormat.of().parseHex("302a300506032b656e032100");

    private final KeyPair pair;
    private final byte[] publicBytes;

    private Ephemeral(KeyPair pair) {
        this.pair = pair;
        byte[] encoded = pair.getPublic().getEncoded();
        this.publicBytes = Arrays.copyOfRange(encoded, encoded.length - BYTES, encoded.length);
    }

    static Ephemeral generate(SecureRandom random) {
        try {
            KeyPairGenerator generator = KeyPairGenerator.getInstance("X25519");
            generator.initialize(NamedParameterSpec.X25519, random);
            return new Ephemeral(generator.generateKeyPair());
        } catch (GeneralSecurityException e) {
            throw new IllegalStateException("the JDK must provide X25519", e);
        }
    }

    /** The 32-byte public value (a copy). */
    byte[] publicBytes() {
        return publicBytes.clone();
    }

    /**
     * The shared secret with the peer's 32-byte public value.
     *
     * @throws Malformed when the JDK refuses the peer's value (a point of small order, which would
     *                   make the secret predictable)
     */
    byte[] agree(byte[] peerPublic) throws Malformed {
        byte[] encoded = Arrays.copyOf(X509_PREFIX, X509_PREFIX.length + BYTES);
        System.arraycopy(peerPublic, 0, encoded, X509_PREFIX.length, BYTES);
        try {
            KeyAgreement agreement = KeyAgreement.getInstance("X25519");
            agreement.init(pair.getPrivate());
            agreement.doPhase(KeyFactory.getInstance("X25519").generatePublic(new X509EncodedKeySpec(encoded)), true);
            return agreement.generateSecret();
        } catch (GeneralSecurityException e) {
            throw new Malformed("ephemeral key refused: " + e.getMessage());
        }
    }
}
