package net.smc.core.security;

import java.util.Objects;

/**
 * What a vehicle trusts: one mission authority's public key, and optionally one mission. Every
 * credential a vehicle accepts is checked against it.
 *
 * @param authority the mission authority's Ed25519 public key
 * @param mission   the mission a credential must name, or null to accept any mission of the authority
 */
public record TrustAnchor(VerificationKey authority, String mission) {

    public TrustAnchor {
        Objects.requireNonNull(authority, "authority");
        if (mission != null) {
            WireNames.encode(mission, "trust anchor", "mission");
        }
    }

    /** Trusts {@code authority} for any mission. */
    public static TrustAnchor of(VerificationKey authority) {
        return new TrustAnchor(authority, null);
    }

    /**
     * Checks, in this order: the issuing authority, the signature, the validity period at
     * {@code nowMillis} (not-before is inclusive, expiry exclusive), the mission.
     */
    public CredentialStatus verify(Credential credential, long nowMillis) {
        if (!credential.authority().equals(authority.id())) {
            return CredentialStatus.FOREIGN_AUTHORITY;
        }
        if (!credential.signedBy(authority)) {
            return CredentialStatus.BAD_SIGNATURE;
        }
        return checkTimeAndMission(credential, nowMillis);
    }

    /** The checks that follow a good signature: validity period and mission. */
    CredentialStatus checkTimeAndMission(Credential credential, long nowMillis) {
        if (nowMillis < credential.notBeforeMillis()) {
            return CredentialStatus.NOT_YET_VALID;
        }
        if (nowMillis >= credential.expiresMillis()) {
            return CredentialStatus.EXPIRED;
        }
        if (mission != null && !mission.equals(credential.mission())) {
            return CredentialStatus.WRONG_MISSION;
        }
        return CredentialStatus.VALID;
    }
}
