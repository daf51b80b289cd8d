package net.smc.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.DatagramSocket;
import java.net.InetSocketAddress;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import net.smc.core.transport.udp.StatusResponder;
import net.smc.core.transport.udp.UdpSettings;
import net.smc.core.transport.udp.UdpTransport;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code smc status} against a node's status responder on UDP loopback, a silent port, and bad arguments. */
class StatusCommandTest {
    private static final String VIEW = "{\"id\":\"uav1\",\"roles\":[\"surveyor\"],\"peers\":2}";

    @TempDir
    Path dir;

    private Smc smc;
    private final ExecutorService cell = Executors.newSingleThreadExecutor();
    private UdpTransport udp;

    @BeforeEach
    void setUp() {
        smc = Smc.in(dir);
    }

    @AfterEach
    void close() {
        if (udp != null) {
            udp.close();
        }
        cell.shutdownNow();
    }

    /** A port free on this machine now, for the test node's broadcast channel. */
    private static int freePort() {
        try (DatagramSocket probe = new DatagramSocket(new InetSocketAddress("0.0.0.0", 0))) {
            return probe.getLocalPort();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    @Test
    void runningNode_printsItsJson_exitStatus0() throws Exception {
        udp = UdpTransport.open(UdpSettings.defaults().withBroadcast("127.255.255.255", freePort()), cell);
        StatusResponder responder = new StatusResponder(udp, () -> VIEW);
        responder.setReceiver((from, data) -> { });

        Smc.Result result = smc.run("status", "--node", udp.localAddress().toString());

        assertEquals("", result.err());
        assertEquals(List.of(VIEW), result.outLines());
        assertEquals(0, result.status());
        assertEquals(1, responder.answered());
    }

    @Test
    void noAnswer_isOneLineNamingTheNode_exitStatus1() throws Exception {
        try (DatagramSocket silent = new DatagramSocket(new InetSocketAddress("127.0.0.1", 0))) {
            String node = "127.0.0.1:" + silent.getLocalPort();

            Smc.Result result = smc.run("status", "--node", node, "--timeout", "200");

            assertEquals(List.of("smc status: no status reply from " + node + " within 200 ms (3 queries sent); "
                    + "is a node running there?"), result.errLines());
            assertEquals("", result.out());
            assertEquals(1, result.status());
        }
    }

    @Test
    void badNodeAddress_isAUsageErrorSayingWhatIsExpected_exitStatus2() {
        Smc.Result result = smc.run("status", "--node", "uav1:4000");

        assertEquals(2, result.status());
        assertEquals("smc status: Invalid value for option '--node': 'uav1:4000' is not ADDR:PORT; expected an IPv4 "
                + "address and a UDP port 1-65535, e.g. 127.0.0.1:4000", result.errLines().get(0));
        assertTrue(result.err().contains("Usage: smc status "), result.err());
        assertEquals("", result.out());
    }

    @Test
    void nodeWithoutPort_isAUsageError() {
        Smc.Result result = smc.run("status", "--node", "127.0.0.1");

        assertEquals(2, result.status());
        assertTrue(result.errLines().get(0).startsWith("smc status: Invalid value for option '--node': '127.0.0.1' is "
                + "not ADDR:PORT"), result.err());
    }

    @Test
    void badTimeout_isAUsageError() {
        Smc.Result result = smc.run("status", "--node", "127.0.0.1:4000", "--timeout", "0");

        assertEquals(2, result.status());
        assertEquals("smc status: Invalid value for option '--timeout': '0' is not a timeout; expected milliseconds, "
                + "1 to 600000, e.g. 500", result.errLines().get(0));
    }

    @Test
    void missingNode_isAUsageError() {
        Smc.Result result = smc.run("status");

        assertEquals(2, result.status());
        assertTrue(result.errLines().get(0).startsWith("smc status: Missing required option: '--node=ADDR:PORT'"),
                result.err());
    }

    @Test
    void help_explainsTheExitStatuses() {
        Smc.Result result = smc.run("status", "--help");

        assertEquals(0, result.status());
        assertTrue(result.out().startsWith("Usage: smc status "), result.out());
        assertTrue(result.out().contains("1   no answer within the timeout"), result.out());
        assertTrue(smc.run("--help").out().contains("status"));
    }
}
