package net.smc.core.security;

import java.util.Optional;

import net.smc.core.transport.Transport;

/**
 * A {@link Transport} that says who sent each payload, proven rather than claimed. A cell whose
 * transport is one of these trusts only the proven sender: the Communication-Manager drops a
 * message whose envelope names anyone else.
 *
 * <p>Two implementations: {@link SecureTransport} (signatures, sessions and MACs, for real networks)
 * and {@link IdealAuthentication}'s endpoints (for simulation, where the network itself knows who
 * sent a datagram and only the credential check is real).
 */
public interface AuthenticatingTransport extends Transport {

    /**
     * Registers the receiver of authenticated payloads, instead of {@link #setReceiver}.
     *
     * @throws IllegalStateException when a receiver is already set
     */
    void setAuthenticatedReceiver(AuthenticatedReceiver receiver);

    /** The credential vehicle {@code peer} authenticated with, once it has. */
    Optional<Credential> credentialOf(String peer);
}
