package net.smc.core.security;

import java.util.Optional;

import net.smc.core.transport.Address;
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
     * offered to it. None by default ({@link UnverifiedTest#NONE}): every payload is checked.
     */
    void setUnverifiedFilter(UnverifiedTest ignorable);

    /**
     * Holds the signed datagrams whose payload {@code readable} accepts, unchecked, and hands their
     * payloads to {@code receiver} to read first: a manager that hears a hundred vehicles answer its
     * discovery and seats ten reads the answers to choose whom to contact, and pays the credential
     * check and the key agreement of a first contact only for those ({@link #checkHeld}). Nothing a
     * held payload says is proven (not its sender either): a forged one can only make the receiver
     * check it, which it fails. The newest datagram per source address is held, a bounded number in
     * all (the oldest goes first). Payloads under a session or the team key are checked by a MAC and
     * delivered as usual. None by default: every payload is checked as it comes.
     */
    void holdUnverified(UnverifiedTest readable, UnverifiedReceiver receiver);

    /**
     * Checks the datagram held from {@code from} now, as if it had just arrived: when it passes every
     * check its payload goes to the authenticated receiver (on this thread, before this returns).
     *
     * @return whether a datagram was held from {@code from} (it is no longer held, passed or not)
     */
    boolean checkHeld(Address from);

    /**
     * Sends {@code data} to {@code to} as {@link #send} does, but starts no session: signed when there
     * is none. For a message its receiver may read before checking it and answer by contacting the
     * sender (a discovery reply): a vehicle that answers many managers then shakes hands only with
     * those that contact it.
     */
    void sendWithoutHandshake(Address to, byte[] data);
}
