package net.smc.core.transport;

/**
 * Takes the datagrams that arrive at a {@link Transport}; a cell registers one, usually its
 * message router, which decodes and dispatches.
 */
@FunctionalInterface
public interface Receiver {

    /**
     * Fires once for each datagram that arrives for this cell (unicast to it, or a broadcast by
     * another cell), on the cell's thread, one call at a time, never after the transport is closed.
     *
     * @param from the address the datagram came from: the sender's own {@link Transport#localAddress()},
     *             so a reply sent there reaches the sender, for broadcasts too
     * @param data the payload, a fresh array that now belongs to the receiver
     */
    void onDatagram(Address from, byte[] data);
}
