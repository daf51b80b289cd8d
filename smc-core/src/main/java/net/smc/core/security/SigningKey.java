package net.smc.core.security;

import java.security.SecureRandom;
import java.util.Arrays;
import java.util.Objects;

import org.bouncycastle.math.ec.rfc8032.Ed25519;

/**
 * An Ed25519 key pair: a vehicle's identity, or the mission authority's. Ed25519 because its keys
 * (32 bytes) and signatures (64 bytes) are small enough for a 1,400-byte datagram, and signing is
 * deterministic, so a simulated run replays exactly. The arithmetic is Bouncy Castle's RFC 8032
 * code, which signs and verifies about ten times faster than the JDK 17's provider (whose keys and
 * signatures are the same bytes: {@code SigningKeyTest} checks both ways).
 *
 * <p>Holds the private seed; {@link #toString()} never shows it.
 */
public final class SigningKey {
    /** Length of an Ed25519 signature. */
    public static final int SIGNATURE_BYTES = 64;
    /** Length of an Ed25519 private key (the RFC 8032 seed). */
    public static final int SEED_BYTES = 32;

    private final byte[] seed;
    /** The public key's 32 bytes, kept so that signing need not derive them again. */
    private final byte[] publicBytes;
    private final VerificationKey verificationKey;

    private SigningKey(byte[] seed, VerificationKey verificationKey) {
        this.seed = seed;
        this.publicBytes = verificationKey.bytes();
        this.verificationKey = verificationKey;
    }

    /**
     * A new key pair drawn from {@code random}: its 32-byte seed is the next 32 bytes of
     * {@code random}, as the JDK's own generator draws it, so a seeded generator gives the same key
     * pair as it always did.
     */
    public static SigningKey generate(SecureRandom random) {
        Objects.requireNonNull(random, "random");
        byte[] seed = new byte[SEED_BYTES];
        random.nextBytes(seed);
        byte[] publicKey = new byte[VerificationKey.BYTES];
        Ed25519.generatePublicKey(seed, 0, publicKey, 0);
        return new SigningKey(seed, VerificationKey.of(publicKey));
    }

    /**
     * The key pair with this seed and public key, as a key file stores them; the two are checked
     * to belong together (the public key is derived from the seed and compared).
     *
     * @throws IllegalArgumentException when the seed is not 32 bytes or the public key is not its pair
     */
    public static SigningKey of(byte[] seed, VerificationKey publicKey) {
        Objects.requireNonNull(seed, "seed");
        Objects.requireNonNull(publicKey, "publicKey");
        if (seed.length != SEED_BYTES) {
            throw new IllegalArgumentException("an Ed25519 private key is " + SEED_BYTES + " bytes; got " + seed.length);
        }
        byte[] derived = new byte[VerificationKey.BYTES];
        Ed25519.generatePublicKey(seed, 0, derived, 0);
        if (!Arrays.equals(derived, publicKey.bytes())) {
            throw new IllegalArgumentException("the public key " + publicKey.id() + " is not the pair of the private key it came with");
        }
        return new SigningKey(seed.clone(), publicKey);
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
        Objects.checkFromIndexSize(offset, length, data.length);
        byte[] signature = new byte[SIGNATURE_BYTES];
        Ed25519.sign(seed, 0, publicBytes, 0, data, offset, length, signature, 0);
        return signature;
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
