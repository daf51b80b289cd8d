package net.smc.core.security;

/**
 * Why a {@link SecureEndpoint} refused a datagram. Each reason has its own counter
 * ({@link SecurityCounters#rejected(Rejection)}); a refused datagram changes nothing else.
 */
public enum Rejection {
    /** Does not parse: unknown version or kind, truncated, a length over its limit, text that is not UTF-8, trailing bytes. */
    MALFORMED,
    /** A datagram or handshake signature, or the authority's signature of the attached credential, does not verify. */
    BAD_SIGNATURE,
    /** A MAC'd or key-carrying message from a vehicle with no session with this one (never shook hands, or restarted). */
    UNKNOWN_SENDER,
    /** The sender's credential has expired. */
    EXPIRED_CREDENTIAL,
    /** The sender's credential is not valid yet. */
    CREDENTIAL_NOT_YET_VALID,
    /** The sender's credential was issued by an authority this vehicle does not trust. */
    FOREIGN_AUTHORITY,
    /** The sender's credential is for another mission than the one trusted. */
    WRONG_MISSION,
    /**
     * A counter this receiver has seen from the sender, or older than any it still remembers; or a
     * handshake older than the newest taken from the sender.
     */
    REPLAY,
    /** A counter whose time lies further from the receiver's clock than the freshness window. */
    STALE,
    /** The MAC (or the AES-GCM tag of a team key) does not verify: altered, or under another key. */
    BAD_MAC,
    /** A handshake addressed to another vehicle, or a datagram claiming this vehicle's own id (a reflection). */
    NOT_FOR_ME,
    /** A team broadcast under a team key this vehicle does not hold. */
    NO_TEAM_KEY
}
