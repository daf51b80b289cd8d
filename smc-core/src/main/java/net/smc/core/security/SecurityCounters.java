package net.smc.core.security;

import java.util.Collections;
import java.util.EnumMap;
import java.util.Map;

/**
 * What a {@link SecureEndpoint} did (a snapshot). Every datagram given to
 * {@link SecureEndpoint#unwrap} ends in exactly one of {@code delivered}, a handshake
 * ({@code keysAgreed}, {@code hellosRepeated}, {@code hellosOffered}), {@code teamKeysInstalled}, or one {@code rejected}
 * reason.
 *
 * @param signedWrapped     payloads wrapped with a signature
 * @param pairWrapped       payloads wrapped with a session MAC
 * @param teamWrapped       payloads wrapped with the team MAC
 * @param hellosSent        handshakes sent, replies included
 * @param keysAgreed        handshakes taken that brought a new key and set up a session
 * @param hellosRepeated    handshakes taken that brought nothing new
 * @param hellosOffered     handshakes taken that did not echo this side's current key (a first step, or a replay):
 *                          answered, nothing agreed
 * @param teamKeysSent      team keys sealed for a peer
 * @param teamKeysInstalled team keys received and installed
 * @param delivered         payloads that passed every check
 * @param rejected          refused datagrams per reason (every reason present, zero or more)
 */
public record SecurityCounters(long signedWrapped, long pairWrapped, long teamWrapped, long hellosSent, long keysAgreed,
                               long hellosRepeated, long hellosOffered, long teamKeysSent, long teamKeysInstalled, long delivered,
                               Map<Rejection, Long> rejected) {

    public SecurityCounters {
        rejected = Collections.unmodifiableMap(new EnumMap<>(rejected));
    }

    /** Datagrams refused for {@code reason}. */
    public long rejected(Rejection reason) {
        return rejected.getOrDefault(reason, 0L);
    }

    /** Datagrams refused for any reason. */
    public long rejectedTotal() {
        return rejected.values().stream().mapToLong(Long::longValue).sum();
    }

    /** Datagrams unwrapped, whatever became of them. */
    public long unwrapped() {
        return delivered + keysAgreed + hellosRepeated + hellosOffered + teamKeysInstalled + rejectedTotal();
    }
}
