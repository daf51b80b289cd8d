package net.smc.core.security;

import java.util.Arrays;
import java.util.Base64;
import java.util.Objects;

import org.bouncycastle.math.ec.rfc8032.Ed25519;

/**
 * An Ed25519 public key: what a vehicle's credential vouches for, and what a team trusts in its
 * mission authority. Kept as the 32 raw bytes of RFC 8032 (the compact form a credential and a
 * key file carry) and decoded into a curve point once, here, so each verification starts from it.
 *
 * <p>Immutable; equal when the bytes are equal.
 */
public final class VerificationKey {
    /** Length of a raw Ed25519 public key. */
    public static final int BYTES = 32;

    private final byte[] raw;
    /** The decoded point, or null when the bytes are no point of the curve (then nothing verifies). */
    private final Ed25519.PublicPoint point;
    private final KeyId id;

    private VerificationKey(byte[] raw) {
        this.raw = raw;
        this.point = Ed25519.validatePublicKeyPartialExport(raw, 0);
        this.id = KeyId.of(raw);
    }

    /**
     * The key with these 32 raw bytes. Bytes that are no point of the curve make a key that
     * verifies nothing (as a key the JDK accepted but could not use), not an exception: a
     * credential carrying them is refused when its signature is checked.
     *
     * @throws IllegalArgumentException when there are not 32 bytes
     */
    public static VerificationKey of(byte[] raw) {
        Objects.requireNonNull(raw, "raw");
        if (raw.length != BYTES) {
            throw new IllegalArgumentException("an Ed25519 public key is " + BYTES + " bytes; got " + raw.length);
        }
        return new VerificationKey(raw.clone());
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
     * {@code data[offset, offset + length)}. A malformed signature (or a key that is no point of
     * the curve) is simply not valid: hostile input must not throw.
     */
    boolean verify(byte[] data, int offset, int length, byte[] signature, int sigOffset) {
        if (point == null || sigOffset < 0 || signature.length - sigOffset < SigningKey.SIGNATURE_BYTES
                || offset < 0 || length < 0 || data.length - offset < length) {
            return false;
        }
        try {
            return Ed25519.verify(signature, sigOffset, point, data, offset, length);
        } catch (RuntimeException e) {
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
