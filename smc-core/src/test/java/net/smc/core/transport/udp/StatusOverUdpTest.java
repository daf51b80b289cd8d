package net.smc.core.transport.udp;

import static java.nio.charset.StandardCharsets.UTF_8;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetSocketAddress;
import java.time.Duration;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;

import net.smc.core.transport.Recorder;
import net.smc.core.transport.Signal;
import net.smc.core.transport.udp.StatusClient;
import net.smc.core.transport.udp.StatusResponder;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/** {@link StatusClient} against a {@link StatusResponder} on real UDP loopback. */
class StatusOverUdpTest {
    private final Signal signal = new Signal();
    private final ExecutorService cell = Executors.newSingleThreadExecutor();
    private final UdpSettings settings = UdpSettings.defaults().withBroadcast("127.255.255.255", FreePort.udp());
    private UdpTransport udp;

    @AfterEach
    void close() {
        if (udp != null) {
            udp.close();
        }
        cell.shutdownNow();
    }

    /** A fake node on its own socket: answers each query with {@code reply}; another socket answers first with a valid view. */
    private static String askFake(byte[] reply) throws Exception {
        try (DatagramSocket node = new DatagramSocket(new InetSocketAddress("127.0.0.1", 0));
             DatagramSocket other = new DatagramSocket(new InetSocketAddress("127.0.0.1", 0))) {
            Thread answerer = new Thread(() -> {
                try {
                    DatagramPacket q = new DatagramPacket(new byte[1024], 1024);
                    node.receive(q);
                    byte[] forged = "SMC!STAT\u0002{\"forged\":true}".getBytes(UTF_8);
                    other.send(new DatagramPacket(forged, forged.length, q.getSocketAddress()));   // not the node asked
                    node.send(new DatagramPacket(reply, reply.length, q.getSocketAddress()));
                } catch (IOException e) {
                    throw new UncheckedIOException(e);
                }
            });
            answerer.start();
            try {
                return StatusClient.query((InetSocketAddress) node.getLocalSocketAddress(), Duration.ofSeconds(5));
            } finally {
                answerer.join(10_000);
            }
        }
    }

    @Test
    void theClientTakesAnAnswerOnlyFromTheAddressItAsked() throws Exception {
        assertEquals("{\"id\":\"real\"}", askFake("SMC!STAT\u0002{\"id\":\"real\"}".getBytes(UTF_8)));
    }

    /** Bytes that are not UTF-8 are refused, not printed as replacement characters. */
    @Test
    void anAnswerThatIsNotUtf8_isAClearError() {
        byte[] header = "SMC!STAT\u0002{\"id\":\"".getBytes(UTF_8);
        byte[] reply = java.util.Arrays.copyOf(header, header.length + 3);
        reply[header.length] = (byte) 0xFF;
        reply[header.length + 1] = '"';
        reply[header.length + 2] = '}';
        IOException e = assertThrows(IOException.class, () -> askFake(reply));
        assertTrue(e.getMessage().contains("is not valid UTF-8"), e.getMessage());
    }

    @Test
    void anAnswerThatIsNotValidJson_isAClearError() {
        IOException e = assertThrows(IOException.class, () -> askFake("SMC!STAT\u0002{\"id\": oops".getBytes(UTF_8)));
        assertTrue(e.getMessage().contains("is not valid JSON"), e.getMessage());
    }

    @Test
    void query_returnsTheViewOfTheNode() throws Exception {
        udp = UdpTransport.open(settings, cell);
        StatusResponder responder = new StatusResponder(udp, () -> "{\"id\":\"uav1\"}");
        responder.setReceiver(new Recorder(signal));

        String json = StatusClient.query(udp.localAddress().toInetSocketAddress(), Duration.ofSeconds(5));

        assertEquals("{\"id\":\"uav1\"}", json);
        assertEquals(1, responder.answered());
    }

    @Test
    void cellTraffic_stillReachesTheCell_besideQueries() throws Exception {
        udp = UdpTransport.open(settings, cell);
        Recorder cellGot = new Recorder(signal);
        StatusResponder responder = new StatusResponder(udp, () -> "{}");
        responder.setReceiver(cellGot);

        StatusClient.query(udp.localAddress().toInetSocketAddress(), Duration.ofSeconds(5));
        try (DatagramSocket peer = new DatagramSocket(new InetSocketAddress("127.0.0.1", 0))) {
            peer.send(new DatagramPacket("hello".getBytes(UTF_8), 5, udp.localAddress().toInetSocketAddress()));
            assertTrue(signal.await(() -> cellGot.count() == 1, UdpTransportContractTest.AWAIT_MILLIS), "hang guard");
            assertEquals("127.0.0.1:" + peer.getLocalPort() + " hello", cellGot.received().get(0));
        }
        assertEquals(1, responder.passedOn());
    }

    @Test
    void silentNode_failsAfterTheTimeout_namingTheAddress() throws Exception {
        try (DatagramSocket silent = new DatagramSocket(new InetSocketAddress("127.0.0.1", 0))) {
            InetSocketAddress node = new InetSocketAddress("127.0.0.1", silent.getLocalPort());
            long start = System.nanoTime();

            IOException e = assertThrows(IOException.class, () -> StatusClient.query(node, Duration.ofMillis(300)));

            long tookMillis = (System.nanoTime() - start) / 1_000_000;
            assertEquals("no status reply from 127.0.0.1:" + node.getPort() + " within 300 ms (3 queries sent); "
                    + "is a node running there?", e.getMessage());
            assertTrue(tookMillis >= 290, "waited the whole timeout, took " + tookMillis + " ms");
            byte[] buffer = new byte[1024];
            DatagramPacket packet = new DatagramPacket(buffer, buffer.length);
            silent.setSoTimeout(1_000);
            silent.receive(packet);
            assertEquals(StatusResponder.QUERY_BYTES, packet.getLength(), "the node was sent a query");
        }
    }

    @Test
    void otherDatagramsToTheClient_areIgnored() throws Exception {
        try (DatagramSocket node = new DatagramSocket(new InetSocketAddress("127.0.0.1", 0))) {
            Thread answerer = new Thread(() -> answerAfterNoise(node));
            answerer.start();

            String json = StatusClient.query(new InetSocketAddress("127.0.0.1", node.getLocalPort()), Duration.ofSeconds(5));

            assertEquals("{\"ok\":true}", json);
            answerer.join(5_000);
        }
    }

    /** Answers the first query with a datagram that is not a reply, then with a reply. */
    private static void answerAfterNoise(DatagramSocket node) {
        try {
            DatagramPacket query = new DatagramPacket(new byte[1024], 1024);
            node.receive(query);
            byte[] noise = "SMC!STAT\u0001{\"old\":true}".getBytes(UTF_8);
            node.send(new DatagramPacket(noise, noise.length, query.getSocketAddress()));
            byte[] reply = "SMC!STAT\u0002{\"ok\":true}".getBytes(UTF_8);
            node.send(new DatagramPacket(reply, reply.length, query.getSocketAddress()));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    @Test
    void timeout_mustBeAtLeastAMillisecond() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> StatusClient.query(new InetSocketAddress("127.0.0.1", 9), Duration.ZERO));
        assertEquals("timeout PT0S is too short; it must be at least 1 ms", e.getMessage());
    }
}
