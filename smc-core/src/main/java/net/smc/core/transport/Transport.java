package net.smc.core.transport;

/**
 * A cell's network endpoint: it sends datagrams to one address or to every cell in reach, and
 * hands the datagrams that arrive to one {@link Receiver}. Delivery is unreliable, as UDP is:
 * datagrams may be lost, duplicated or re-ordered; protocols that need more build it on top.
 *
 * <p>Two implementations: the in-memory network with fault injection
 * ({@code net.smc.core.transport.sim.InMemoryNetwork}) and Netty UDP
 * ({@code net.smc.core.transport.udp.UdpTransport}); one contract test suite runs against both.
 *
 * <p>Threading: a cell calls these methods from its own thread, and the receiver is called on that
 * thread too, so protocol code needs no locks. Sending never calls the receiver synchronously, not
 * even for a datagram a cell sends to itself.
 *
 * <p>See <a href="doc-files/transport.md">the transport design note</a>.
 */
public interface Transport extends AutoCloseable {

    /**
     * The most bytes one datagram may carry. Below the usual 1500-byte Ethernet MTU minus IP and
     * UDP headers, so a datagram is never fragmented.
     */
    int MAX_DATAGRAM_BYTES = 1400;

    /**
     * The most bytes one datagram handed to this endpoint may carry: {@link #MAX_DATAGRAM_BYTES}
     * less what the layers below add to each datagram (an authentication envelope). Messages larger
     * than this are cut into fragments that fit it.
     */
    default int datagramCapacity() {
        return MAX_DATAGRAM_BYTES;
    }

    /** Where other cells reach this one; the {@code from} address its datagrams carry. */
    Address localAddress();

    /**
     * Sends a datagram to one address. The data is copied before this method returns, so the
     * caller may reuse the array.
     *
     * @throws DatagramTooLargeException when {@code data} is longer than {@link #MAX_DATAGRAM_BYTES}
     * @throws IllegalStateException     when the transport is closed
     */
    void send(Address to, byte[] data);

    /**
     * Sends a datagram to every other cell in reach; the sender does not receive its own
     * broadcast. The data is copied before this method returns.
     *
     * @throws DatagramTooLargeException when {@code data} is longer than {@link #MAX_DATAGRAM_BYTES}
     * @throws IllegalStateException     when the transport is closed
     */
    void broadcast(byte[] data);

    /**
     * How long from now until the last datagram handed to this endpoint has left it (its transmit
     * queue: a radio sends one datagram after another), in ms; 0 when it has left, or when the
     * endpoint cannot tell (a UDP socket hands datagrams to the kernel). The Message-Sender starts a
     * message's retransmission timer when the message has left, not when it was queued, so that a
     * message behind a queue of others is not retransmitted before its first copy is out.
     */
    default long backlogMillis() {
        return 0;
    }

    /**
     * Registers the one receiver of this endpoint. Datagrams that arrive before it is set are
     * dropped and counted.
     *
     * @throws IllegalStateException when a receiver is already set
     */
    void setReceiver(Receiver receiver);

    /**
     * Stops sending and receiving and releases what the endpoint holds. No receiver call starts
     * after it returns. Closing again does nothing.
     */
    @Override
    void close();
}
