package net.smc.core.security;

import java.nio.ByteBuffer;
import java.util.Arrays;
import java.util.Base64;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Objects;

import org.bouncycastle.math.ec.rfc8032.Ed25519;

/**
 * An Ed25519 public key: what a vehicle's credential vouches for, and what a team trusts in its
 * mission authority. Kept as the 32 raw bytes of RFC 8032 (the compact form a credential and a
 * key file carry) and decoded into a curve point once, here, so each verification starts from it.
 *
 * <p>Immutable; equal when the bytes are equal. The keys made lately are kept by their bytes
 * ({@value #KEPT} of them), so a credential that arrives with every signed datagram of a peer does
 * not decode its point again each time. A signature found valid is remembered with its bytes
 * ({@link VerifiedSignatures}): the same signed datagram delivered to several cells of one process
 * is verified once.
 *
 * <p>Thread-safe.
 */
public final class VerificationKey {
    /** Length of a raw Ed25519 public key. */
    public static final int BYTES = 32;
    /** Keys kept by their bytes for reuse. */
    static final int KEPT = 4096;

    private static final Map<ByteBuffer, VerificationKey> RECENT = new LinkedHashMap<>(2 * KEPT, 0.75f, true) {
        @Override
        protected boolean removeEldestEntry(Map.Entry<ByteBuffer, VerificationKey> eldest) {
            return size() > KEPT;
        }
    };

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
        ByteBuffer name = ByteBuffer.wrap(raw);
        synchronized (RECENT) {
            VerificationKey kept = RECENT.get(name);
            if (kept != null) {
                return kept;
            }
        }
        VerificationKey key = new VerificationKey(raw.clone());
        synchronized (RECENT) {
            RECENT.put(ByteBuffer.wrap(key.raw), key);
        }
        return key;
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
        if (VerifiedSignatures.SHARED.contains(this, data, offset, length, signature, sigOffset)) {
            return true;
        }
        boolean valid;
        try {
            valid = Ed25519.verify(signature, sigOffset, point, data, offset, length);
        } catch (RuntimeException e) {
            return false;
        }
        if (valid) {
            VerifiedSignatures.SHARED.add(this, data, offset, length, signature, sigOffset);
        }
        return valid;
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
