package net.smc.core.security;

/** The outcome of checking a {@link Credential} against a {@link TrustAnchor} at one instant; each failure has its own cause. */
public enum CredentialStatus {
    /** Signed by the trusted authority, within its validity, for the trusted mission. */
    VALID,
    /** WireNames another authority's key: it may be genuine, but not for this team. */
    FOREIGN_AUTHORITY,
    /** WireNames the trusted authority, but its signature does not verify: forged or altered. */
    BAD_SIGNATURE,
    /** Its not-before lies in the future. */
    NOT_YET_VALID,
    /** Its expiry has passed. */
    EXPIRED,
    /** Genuine and current, but for another mission. */
    WRONG_MISSION
}
