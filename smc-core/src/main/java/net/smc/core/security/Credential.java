package net.smc.core.security;

import java.util.Arrays;
import java.util.Base64;
import java.util.Objects;

/**
 * A mission authority's signed statement that a vehicle holds a key and may join a mission until
 * a time: what a vehicle shows to be let into a team. The paper defers its authentication protocol
 * (section IV-B); this is the part of it that an authority prepares before the mission, so that
 * vehicles can check each other later with no authority in reach.
 *
 * <p>Issue one with {@link #issue}; check one with {@link TrustAnchor#verify}. The binary form
 * ({@link #encode()}, at most 251 bytes) is versioned and documented in {@code CredentialCodec}
 * and in <a href="doc-files/security.md">the security design note</a>.
 *
 * @param claims    what is vouched for
 * @param authority the id of the key that signed it
 * @param signature the authority's Ed25519 signature (64 bytes)
 */
public record Credential(Claims claims, KeyId authority, byte[] signature) {

    public Credential {
        Objects.requireNonNull(claims, "claims");
        Objects.requireNonNull(authority, "authority");
        Objects.requireNonNull(signature, "signature");
        if (signature.length != SigningKey.SIGNATURE_BYTES) {
            throw new IllegalArgumentException("credential of '" + claims.vehicleId() + "': signature is " + signature.length
                    + " bytes; an Ed25519 signature is " + SigningKey.SIGNATURE_BYTES);
        }
        signature = signature.clone();
    }

    /** The credential {@code authority} signs for {@code claims}. */
    public static Credential issue(Claims claims, SigningKey authority) {
        KeyId id = authority.verificationKey().id();
        byte[] signature = authority.sign(CredentialCodec.toBeSigned(CredentialCodec.body(claims, id)));
        return new Credential(claims, id, signature);
    }

    /**
     * Reads the binary form.
     *
     * @throws CredentialFormatException naming the field, its byte offset and the rule it breaks
     */
    public static Credential decode(byte[] encoded) throws CredentialFormatException {
        try {
            return CredentialCodec.decode(encoded, 0, encoded.length);
        } catch (Malformed e) {
            throw new CredentialFormatException(e.getMessage());
        }
    }

    /** The binary form, version 1. */
    public byte[] encode() {
        return CredentialCodec.encode(this);
    }

    /** Whether {@code authorityKey} signed exactly these claims; says nothing about time or mission. */
    boolean signedBy(VerificationKey authorityKey) {
        return authorityKey.id().equals(authority)
                && authorityKey.verify(CredentialCodec.toBeSigned(CredentialCodec.body(claims, authority)), signature);
    }

    /** A copy of the signature. */
    @Override
    public byte[] signature() {
        return signature.clone();
    }

    public String vehicleId() {
        return claims.vehicleId();
    }

    public VerificationKey vehicleKey() {
        return claims.vehicleKey();
    }

    public String mission() {
        return claims.mission();
    }

    public long notBeforeMillis() {
        return claims.notBeforeMillis();
    }

    public long expiresMillis() {
        return claims.expiresMillis();
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof Credential other && claims.equals(other.claims) && authority.equals(other.authority)
                && Arrays.equals(signature, other.signature);
    }

    @Override
    public int hashCode() {
        return Objects.hash(claims, authority, Arrays.hashCode(signature));
    }

    @Override
    public String toString() {
        return "Credential[" + claims + ", authority=" + authority + ", signature="
                + Base64.getEncoder().encodeToString(signature).substring(0, 12) + "...]";
    }
}
