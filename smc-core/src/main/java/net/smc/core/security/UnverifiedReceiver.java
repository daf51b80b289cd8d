package net.smc.core.security;

import net.smc.core.transport.Address;

/**
 * Takes the payloads an {@link AuthenticatingTransport} holds unchecked for its receiver to read
 * first ({@link AuthenticatingTransport#holdUnverified}): nothing in them is proven, not even who
 * sent them, so the receiver may use them only to choose whom to contact, and acts on a payload
 * only once {@link AuthenticatingTransport#checkHeld} has delivered it to its authenticated receiver.
 */
@FunctionalInterface
public interface UnverifiedReceiver {

    /**
     * Fires once for each payload held, on the cell's thread.
     *
     * @param from    the address it came from (not authenticated), the key to check it by
     * @param payload the payload, a fresh array that now belongs to the receiver
     */
    void onUnverified(Address from, byte[] payload);
}
