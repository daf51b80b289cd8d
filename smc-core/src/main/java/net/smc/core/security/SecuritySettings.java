package net.smc.core.security;

/**
 * The tunable numbers of a {@link SecureEndpoint}, with defaults that suit a team on one radio
 * network whose clocks agree to within seconds (GPS time, say).
 *
 * @param freshnessWindowMillis how far, in milliseconds, a message's time (its counter's, which
 *                              follows the sender's clock) may lie from the receiver's clock, either
 *                              way, before it is refused as stale; it also bounds how long a receiver
 *                              must remember counters. At most a day, well inside the 1.5 days either
 *                              way in which the 48 bits of counter a datagram carries name one counter.
 *                              Default 30,000.
 * @param replayWindow          how many recent counters a receiver remembers per sender (per session,
 *                              per team key), so that re-ordered messages still pass but repeats do
 *                              not; a counter at or below the oldest one forgotten is refused. Default 64.
 * @param handshakeRetryMillis  how long, in milliseconds, a handshake may wait for its answer before a
 *                              new one may replace it (and before a crossing handshake from the peer is
 *                              answered instead). Default 1,000.
 */
public record SecuritySettings(long freshnessWindowMillis, int replayWindow, long handshakeRetryMillis) {
    /** 30 s freshness, 64 counters, 1 s handshake retry. */
    public static final SecuritySettings DEFAULTS = new SecuritySettings(30_000, 64, 1_000);

    /** @throws IllegalArgumentException naming the setting, its value and the allowed range */
    public SecuritySettings {
        if (freshnessWindowMillis < 1 || freshnessWindowMillis > 86_400_000) {
            throw new IllegalArgumentException("freshnessWindowMillis " + freshnessWindowMillis
                    + " is out of range; it must be 1 to 86400000 (one day)");
        }
        if (replayWindow < 1 || replayWindow > 4096) {
            throw new IllegalArgumentException("replayWindow " + replayWindow + " is out of range; it must be 1 to 4096");
        }
        if (handshakeRetryMillis < 1) {
            throw new IllegalArgumentException("handshakeRetryMillis " + handshakeRetryMillis + " is out of range; it must be 1 or more");
        }
    }

    public SecuritySettings withFreshnessWindowMillis(long millis) {
        return new SecuritySettings(millis, replayWindow, handshakeRetryMillis);
    }

    public SecuritySettings withReplayWindow(int counters) {
        return new SecuritySettings(freshnessWindowMillis, counters, handshakeRetryMillis);
    }

    public SecuritySettings withHandshakeRetryMillis(long millis) {
        return new SecuritySettings(freshnessWindowMillis, replayWindow, millis);
    }
}
