package net.smc.core.security;

import java.security.GeneralSecurityException;
import java.security.KeyFactory;
import java.security.PublicKey;
import java.security.Signature;
import java.security.spec.X509EncodedKeySpec;
import java.util.Arrays;
import java.util.Base64;
import java.util.HexFormat;
import java.util.Objects;

/**
 * An Ed25519 public key: what a vehicle's credential vouches for, and what a team trusts in its
 * mission authority. Kept as the 32 raw bytes of RFC 8032 (the compact form a credential and a
 * key file carry) and turned into a JDK key once, here.
 *
 * <p>Immutable; equal when the bytes are equal.
 */
public final class VerificationKey {
    /** Length of a raw Ed25519 public key. */
    public static final int BYTES = 32;
    /** The DER prefix that makes 32 raw bytes an X.509 SubjectPublicKeyInfo for Ed25519 (RFC 8410). */
    private static final byte[] X509_PREFIX = HexFormat.of().parseHex("302a300506032b6570032100");

    private final byte[] raw;
    private final PublicKey key;
    private final KeyId id;

    private VerificationKey(byte[] raw, PublicKey key) {
        this.raw = raw;
        this.key = key;
        this.id = KeyId.of(raw);
    }

    /**
     * The key with these 32 raw bytes.
     *
     * @throws IllegalArgumentException when there are not 32 bytes, or the JDK refuses them
     */
    public static VerificationKey of(byte[] raw) {
        Objects.requireNonNull(raw, "raw");
        if (raw.length != BYTES) {
            throw new IllegalArgumentException("an Ed25519 public key is " + BYTES + " bytes; got " + raw.length);
        }
        byte[] encoded = Arrays.copyOf(X509_PREFIX, X509_PREFIX.length + BYTES);
        System.arraycopy(raw, 0, encoded, X509_PREFIX.length, BYTES);
        try {
            return new VerificationKey(raw.clone(), KeyFactory.getInstance("Ed25519").generatePublic(new X509EncodedKeySpec(encoded)));
        } catch (GeneralSecurityException e) {
            throw new IllegalArgumentException("not an Ed25519 public key: " + e.getMessage(), e);
        }
    }

    /** The key of a JDK Ed25519 public key (whose X.509 form ends with the raw bytes). */
    static VerificationKey of(PublicKey key) {
        byte[] encoded = key.getEncoded();
        if (!"EdDSA".equals(key.getAlgorithm()) && !"Ed25519".equals(key.getAlgorithm()) || encoded.length != X509_PREFIX.length + BYTES) {
            throw new IllegalArgumentException("not an Ed25519 public key: " + key.getAlgorithm() + ", " + encoded.length + " bytes encoded");
        }
        return new VerificationKey(Arrays.copyOfRange(encoded, X509_PREFIX.length, encoded.length), key);
    }

    /** The 32 raw bytes (a copy). */
    public byte[] bytes() {
        return raw.clone();
    }

    /** The key's short name. */
    public KeyId id() {
        return id;
    }

    /** Whether {@code signature} is this key's Ed25519 signature of {@code message}; never throws for bad input. */
    public boolean verify(byte[] message, byte[] signature) {
        return verify(message, 0, message.length, signature, 0);
    }

    /**
     * Whether the 64 bytes at {@code signature[sigOffset]} are this key's signature of
     * {@code data[offset, offset + length)}. A malformed signature (or a point the JDK refuses)
     * is simply not valid: hostile input must not throw.
     */
    boolean verify(byte[] data, int offset, int length, byte[] signature, int sigOffset) {
        if (sigOffset < 0 || signature.length - sigOffset < SigningKey.SIGNATURE_BYTES) {
            return false;
        }
        try {
            Signature verifier = Signature.getInstance("Ed25519");
            verifier.initVerify(key);
            verifier.update(data, offset, length);
            return verifier.verify(signature, sigOffset, SigningKey.SIGNATURE_BYTES);
        } catch (GeneralSecurityException e) {
            return false;
        }
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof VerificationKey other && Arrays.equals(raw, other.raw);
    }

    @Override
    public int hashCode() {
        return Arrays.hashCode(raw);
    }

    /** The raw key in base64, and its id. */
    @Override
    public String toString() {
        return Base64.getEncoder().encodeToString(raw) + " (id " + id + ")";
    }
}
