package net.smc.core.discovery;

import java.util.Objects;

/**
 * Decides whether a discovered vehicle's credential is acceptable. A stand-in for the paper's
 * public-key authentication protocol, which comes with the messaging layer: until then a team
 * shares a token ({@link #sharedToken}), which keeps strangers out of a test team but is no
 * security against anyone who hears it.
 */
@FunctionalInterface
public interface CredentialCheck {

    /**
     * @param uav        the vehicle's identifier, as the discovery event gave it
     * @param credential the credential it presented: a PonderTalk value (a string), or the Java
     *                   object a managed-object credential wraps
     */
    boolean accepts(String uav, Object credential);

    /** Accepts exactly the credential {@code token} (compared as a string), from any vehicle. */
    static CredentialCheck sharedToken(String token) {
        Objects.requireNonNull(token, "token");
        if (token.isEmpty()) {
            throw new IllegalArgumentException("a shared token must not be empty: an empty credential would pass");
        }
        return (uav, credential) -> credential instanceof String s && s.equals(token);
    }
}
