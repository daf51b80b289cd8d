package net.smc.core.security;

import java.security.GeneralSecurityException;
import java.security.KeyFactory;
import java.security.KeyPair;
import java.security.KeyPairGenerator;
import java.security.PrivateKey;
import java.security.SecureRandom;
import java.security.Signature;
import java.security.interfaces.EdECPrivateKey;
import java.security.spec.EdECPrivateKeySpec;
import java.security.spec.NamedParameterSpec;
import java.util.Arrays;
import java.util.Objects;

/**
 * An Ed25519 key pair: a vehicle's identity, or the mission authority's. Ed25519 because the JDK
 * 17 has it, its keys (32 bytes) and signatures (64 bytes) are small enough for a 1,400-byte
 * datagram, and signing is deterministic, so a simulated run replays exactly.
 *
 * <p>Holds the private seed; {@link #toString()} never shows it.
 */
public final class SigningKey {
    /** Length of an Ed25519 signature. */
    public static final int SIGNATURE_BYTES = 64;
    /** Length of an Ed25519 private key (the RFC 8032 seed). */
    public static final int SEED_BYTES = 32;

    private final byte[] seed;
    private final PrivateKey key;
    private final VerificationKey verificationKey;

    private SigningKey(byte[] seed, PrivateKey key, VerificationKey verificationKey) {
        this.seed = seed;
        this.key = key;
        this.verificationKey = verificationKey;
    }

    /** A new key pair drawn from {@code random}. */
    public static SigningKey generate(SecureRandom random) {
        Objects.requireNonNull(random, "random");
        try {
            KeyPairGenerator generator = KeyPairGenerator.getInstance("Ed25519");
            generator.initialize(NamedParameterSpec.ED25519, random);
            KeyPair pair = generator.generateKeyPair();
            byte[] seed = ((EdECPrivateKey) pair.getPrivate()).getBytes()
                    .orElseThrow(() -> new IllegalStateException("the JDK did not reveal the Ed25519 seed it generated"));
            return new SigningKey(seed, pair.getPrivate(), VerificationKey.of(pair.getPublic()));
        } catch (GeneralSecurityException e) {
            throw new IllegalStateException("the JDK must provide Ed25519", e);
        }
    }

    /**
     * The key pair with this seed and public key, as a key file stores them. The JDK cannot derive
     * the public key from the seed, so both are given, and checked to belong together by signing
     * and verifying a probe.
     *
     * @throws IllegalArgumentException when the seed is not 32 bytes or the public key is not its pair
     */
    public static SigningKey of(byte[] seed, VerificationKey publicKey) {
        Objects.requireNonNull(seed, "seed");
        Objects.requireNonNull(publicKey, "publicKey");
        if (seed.length != SEED_BYTES) {
            throw new IllegalArgumentException("an Ed25519 private key is " + SEED_BYTES + " bytes; got " + seed.length);
        }
        PrivateKey key;
        try {
            key = KeyFactory.getInstance("Ed25519").generatePrivate(new EdECPrivateKeySpec(NamedParameterSpec.ED25519, seed.clone()));
        } catch (GeneralSecurityException e) {
            throw new IllegalArgumentException("not an Ed25519 private key: " + e.getMessage(), e);
        }
        SigningKey signingKey = new SigningKey(seed.clone(), key, publicKey);
        byte[] probe = "smc key pair probe".getBytes(java.nio.charset.StandardCharsets.US_ASCII);
        if (!publicKey.verify(probe, signingKey.sign(probe))) {
            throw new IllegalArgumentException("the public key " + publicKey.id() + " is not the pair of the private key it came with");
        }
        return signingKey;
    }

    /** The public half. */
    public VerificationKey verificationKey() {
        return verificationKey;
    }

    /** The Ed25519 signature of {@code message}. */
    public byte[] sign(byte[] message) {
        return sign(message, 0, message.length);
    }

    /** The Ed25519 signature of {@code data[offset, offset + length)}. */
    byte[] sign(byte[] data, int offset, int length) {
        try {
            Signature signer = Signature.getInstance("Ed25519");
            signer.initSign(key);
            signer.update(data, offset, length);
            return signer.sign();
        } catch (GeneralSecurityException e) {
            throw new IllegalStateException("the JDK refused to sign with its own Ed25519 key", e);
        }
    }

    /** The 32-byte private seed, for a key file (a copy). */
    byte[] seed() {
        return seed.clone();
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof SigningKey other && Arrays.equals(seed, other.seed);
    }

    @Override
    public int hashCode() {
        return verificationKey.hashCode();
    }

    /** WireNames the key by its public id; never shows the private seed. */
    @Override
    public String toString() {
        return "SigningKey[" + verificationKey.id() + "]";
    }
}
