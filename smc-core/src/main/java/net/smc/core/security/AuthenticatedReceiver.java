package net.smc.core.security;

import net.smc.core.transport.Address;

/**
 * Takes the payloads a {@link SecureTransport} has authenticated, with who sent them: what a
 * protocol that checks its sender (role assignment from the parent, heartbeats from a child)
 * registers instead of a plain {@link net.smc.core.transport.Receiver}.
 */
@FunctionalInterface
public interface AuthenticatedReceiver {

    /**
     * Fires once for each payload that passed every check, on the cell's thread.
     *
     * @param sender     the sender's vehicle id, as proven by {@code protection}
     * @param from       the address it came from (not itself authenticated: UDP source addresses can be forged)
     * @param protection how it was protected
     * @param payload    the payload, a fresh array that now belongs to the receiver
     */
    void onMessage(String sender, Address from, Protection protection, byte[] payload);
}
