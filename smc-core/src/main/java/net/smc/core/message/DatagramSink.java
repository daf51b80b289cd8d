package net.smc.core.message;

import java.nio.ByteBuffer;

/**
 * Receives the datagrams of one encoded message, in fragment order.
 *
 * <p>Ownership: the buffer belongs to the {@link MessageEncoder}; it is valid only during the call
 * and is reused for the next datagram. Send it or copy it before returning.
 */
@FunctionalInterface
public interface DatagramSink {
    /** One datagram, from the buffer's position to its limit (at most {@link WireFormat#MAX_DATAGRAM} bytes). */
    void datagram(ByteBuffer datagram);
}
