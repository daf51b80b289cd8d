package net.smc.core.transport.udp;

import net.smc.core.transport.Address;
import net.smc.core.transport.udp.StatusResponder;
import java.io.IOException;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetSocketAddress;
import java.net.SocketTimeoutException;
import java.time.Duration;
import java.util.Objects;

/**
 * Asks a running cell for its status view: the client side of {@link StatusResponder}, for
 * command-line tools ({@code smc status}) and tests, not for cell code (it blocks and opens its own
 * socket).
 *
 * <pre>{@code
 * String json = StatusClient.query(new InetSocketAddress("127.0.0.1", 4001), Duration.ofSeconds(1));
 * }</pre>
 */
public final class StatusClient {
    /** Queries sent within one timeout: a lost query or reply costs a fraction of the time, not all of it. */
    static final int ATTEMPTS = 3;
    private static final com.fasterxml.jackson.databind.ObjectMapper JSON = new com.fasterxml.jackson.databind.ObjectMapper();
    private static final int RECEIVE_BUFFER_BYTES = 2_048;

    private StatusClient() {
    }

    /**
     * Sends a status query to {@code node} and returns the JSON of the first reply. The timeout is
     * split between {@value #ATTEMPTS} queries; datagrams that are not a status reply are ignored.
     *
     * @param node    the cell's unicast address (a resolved IPv4 address and port)
     * @param timeout how long to wait in all, more than zero
     * @throws IOException when no reply comes within the timeout (the message names the address), or
     *                     the socket fails
     */
    public static String query(InetSocketAddress node, Duration timeout) throws IOException {
        Objects.requireNonNull(node, "node");
        Objects.requireNonNull(timeout, "timeout");
        if (node.isUnresolved()) {
            throw new IllegalArgumentException("node address " + node + " is unresolved; it must be an IP address and port");
        }
        long timeoutMillis = timeout.toMillis();
        if (timeoutMillis < 1) {
            throw new IllegalArgumentException("timeout " + timeout + " is too short; it must be at least 1 ms");
        }
        byte[] query = StatusResponder.query(Address.of(node));
        byte[] buffer = new byte[RECEIVE_BUFFER_BYTES];
        long deadline = System.nanoTime() + timeout.toNanos();
        int sent = 0;
        try (DatagramSocket socket = new DatagramSocket()) {
            for (int attempt = 1; attempt <= ATTEMPTS; attempt++) {
                socket.send(new DatagramPacket(query, query.length, node));
                sent++;
                long attemptEnd = attempt == ATTEMPTS ? deadline : System.nanoTime() + timeout.toNanos() / ATTEMPTS;
                String json = awaitReply(socket, node, buffer, Math.min(attemptEnd, deadline));
                if (json != null) {
                    return json;
                }
            }
        }
        throw new IOException("no status reply from " + node.getAddress().getHostAddress() + ":" + node.getPort()
                + " within " + timeoutMillis + " ms (" + sent + " queries sent); is a node running there?");
    }

    /**
     * The JSON of the first status reply from {@code node} before {@code deadline} (a {@link System#nanoTime()}),
     * or null; datagrams from any other address are ignored.
     *
     * @throws IOException when the reply from {@code node} is not valid JSON
     */
    private static String awaitReply(DatagramSocket socket, InetSocketAddress node, byte[] buffer, long deadline) throws IOException {
        while (true) {
            long remainingMillis = (deadline - System.nanoTime()) / 1_000_000;
            if (remainingMillis < 1) {
                return null;
            }
            socket.setSoTimeout((int) Math.min(remainingMillis, Integer.MAX_VALUE));
            DatagramPacket packet = new DatagramPacket(buffer, buffer.length);
            try {
                socket.receive(packet);
            } catch (SocketTimeoutException e) {
                return null;
            }
            if (!node.equals(packet.getSocketAddress())) {
                continue;   // not the node asked: anyone can send to this socket
            }
            String json = StatusResponder.replyJson(packet.getData(), packet.getLength());
            if (json != null) {
                if (!net.smc.core.wire.StrictUtf8.isWellFormed(packet.getData(), StatusResponder.HEADER_BYTES,
                        packet.getLength() - StatusResponder.HEADER_BYTES)) {
                    throw new IOException("the status reply from " + node.getAddress().getHostAddress() + ":" + node.getPort()
                            + " is not valid UTF-8; a status reply is UTF-8 JSON; not printed");
                }
                return validJson(json, node);
            }
        }
    }

    private static String validJson(String json, InetSocketAddress node) throws IOException {
        try (com.fasterxml.jackson.core.JsonParser parser = JSON.getFactory().createParser(json)) {
            JSON.readTree(parser);
            if (parser.nextToken() != null) {
                throw new IOException("trailing data after the JSON value");
            }
        } catch (IOException e) {
            throw new IOException("the status reply from " + node.getAddress().getHostAddress() + ":" + node.getPort()
                    + " is not valid JSON (" + e.getMessage().lines().findFirst().orElse("") + "); not printed", e);
        }
        return json;
    }
}
