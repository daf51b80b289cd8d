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

    /**
     * Sets the receiver's test of a payload not yet authenticated: {@code true} when the receiver
     * would do nothing with it whoever sent it (a cell, a discovery it would not answer). Such a
     * payload is then dropped, and counted, before its costly checks (a signature verification):
     * dropping an authentic one changes nothing and a forged one would have been refused, so no
     * sender gains anything by it. The test must not answer {@code true} for a payload the receiver
     * acts on, and sees the payload's bytes only, not the checked sender. Payloads under a session or
     * the team key are checked by a MAC, which costs about as little as the test, and need not be
     * offered to it. None by default ({@link UnverifiedFilter#NONE}): every payload is checked.
     */
    void setUnverifiedFilter(UnverifiedFilter ignorable);
}
