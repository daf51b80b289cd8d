package net.smc.core.wire;

/** What is wrong with bytes a format reads: the kind a {@link WireErrors} turns into its exception. */
public enum WireProblem {
    /** Fewer bytes remain than the field needs. */
    TRUNCATED,
    /** A length, count or whole form over its limit. */
    OVERSIZED,
    /** Bytes that break a rule of the form (a bad value, bad UTF-8, a non-canonical order). */
    MALFORMED
}
