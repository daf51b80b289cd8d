package net.smc.core.security;

/** How a delivered payload was protected, which says how much its sender id can be trusted. */
public enum Protection {
    /**
     * Signed with the sender's Ed25519 key, its credential attached: anyone who trusts the authority
     * can check it, with no earlier contact. For discovery and first replies.
     */
    SIGNED,
    /** MAC'd under the key of a session with the sender: only that sender could have made it. */
    PAIR_MAC,
    /** MAC'd under the team key: some holder of the team key made it; the sender id is a claim among members. */
    TEAM_MAC
}
