package net.smc.core.transport.udp;

import net.smc.core.transport.Transport;
import net.smc.core.transport.Address;
import static java.nio.charset.StandardCharsets.US_ASCII;
import static java.nio.charset.StandardCharsets.UTF_8;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Supplier;

import net.smc.core.transport.sim.InMemoryNetwork;
import net.smc.core.transport.sim.SimulationScheduler;

import org.junit.jupiter.api.Test;

/** Status queries on the in-memory network: answered, passed by, limited, refused when malformed. */
class StatusResponderTest {
    private static final String VIEW = "{\"id\":\"uav1\",\"roles\":[\"surveyor\"]}";

    private final SimulationScheduler scheduler = new SimulationScheduler();
    private final InMemoryNetwork network = new InMemoryNetwork(scheduler, 1);
    private final Transport cellSide = network.attach(Address.loopback(4001));
    private final Transport asker = network.attach(Address.loopback(4002));
    /** What the cell's own receiver got, as "from text". */
    private final List<String> cellGot = new ArrayList<>();
    /** What came back to the asker, raw. */
    private final List<byte[]> askerGot = new ArrayList<>();

    StatusResponderTest() {
        asker.setReceiver((from, data) -> askerGot.add(data));
    }

    private StatusResponder responder(Supplier<String> view, int perSecond) {
        StatusResponder responder = new StatusResponder(cellSide, view, scheduler, perSecond);
        responder.setReceiver((from, data) -> cellGot.add(from + " " + new String(data, UTF_8)));
        return responder;
    }

    private StatusResponder responder() {
        return responder(() -> VIEW, StatusResponder.DEFAULT_REPLIES_PER_SECOND);
    }

    private void ask(byte[] datagram) {
        asker.send(cellSide.localAddress(), datagram);
        scheduler.runUntilIdle(10_000);
    }

    private List<String> repliesAsJson() {
        return askerGot.stream().map(d -> StatusResponder.replyJson(d, d.length)).toList();
    }

    private static byte[] bytes(String ascii) {
        return ascii.getBytes(US_ASCII);
    }

    @Test
    void query_isAnsweredToItsSender_withTheView() {
        StatusResponder responder = responder();

        ask(StatusResponder.query());

        assertEquals(List.of(VIEW), repliesAsJson());
        assertEquals("SMC!STAT", new String(askerGot.get(0), 0, 8, US_ASCII));
        assertEquals(1, askerGot.get(0)[8]);
        assertEquals(List.of(), cellGot, "a query never reaches the cell");
        assertEquals(1, responder.answered());
        assertEquals(0, responder.passedOn());
    }

    @Test
    void query_isNineBytes_magicThenVersion() {
        assertArrayEquals(bytes("SMC?STAT\u0001"), StatusResponder.query());
    }

    @Test
    void view_isAskedForAtEachQuery_soTheReplyIsCurrent() {
        AtomicInteger calls = new AtomicInteger();
        responder(() -> "{\"n\":" + calls.incrementAndGet() + "}", 20);

        ask(StatusResponder.query());
        ask(StatusResponder.query());

        assertEquals(List.of("{\"n\":1}", "{\"n\":2}"), repliesAsJson());
    }

    @Test
    void ordinaryDatagrams_passThroughUnchanged_unicastAndBroadcast() {
        StatusResponder responder = responder();
        byte[] message = {0x53, 0x4D, 1, 9, 0, -1, 42};

        asker.send(cellSide.localAddress(), message);
        asker.broadcast(bytes("hello all"));
        scheduler.runUntilIdle(10_000);

        assertEquals(List.of("127.0.0.1:4002 " + new String(message, UTF_8), "127.0.0.1:4002 hello all"), cellGot);
        assertEquals(2, responder.passedOn());
        assertEquals(0, responder.answered());
        assertEquals(List.of(), askerGot);
    }

    @Test
    void passedDatagram_arrivesByteForByte() {
        List<byte[]> raw = new ArrayList<>();
        StatusResponder responder = new StatusResponder(cellSide, () -> VIEW, scheduler, 20);
        responder.setReceiver((from, data) -> raw.add(data));
        byte[] message = new byte[Transport.MAX_DATAGRAM_BYTES];
        Arrays.fill(message, (byte) 0xA5);

        ask(message);

        assertEquals(1, raw.size());
        assertArrayEquals(message, raw.get(0));
    }

    @Test
    void datagramShorterThanTheMagic_thatStartsLikeIt_isPassedOn() {
        StatusResponder responder = responder();

        ask(bytes("SMC?STA"));
        ask(bytes("S"));
        ask(new byte[0]);

        assertEquals(List.of("127.0.0.1:4002 SMC?STA", "127.0.0.1:4002 S", "127.0.0.1:4002 "), cellGot);
        assertEquals(0, responder.malformed());
        assertEquals(List.of(), askerGot);
    }

    @Test
    void magicWithAnotherVersionOrMoreBytes_isCountedAsMalformed_notAnsweredNorPassedOn() {
        StatusResponder responder = responder();

        ask(bytes("SMC?STAT"));                      // no version byte
        ask(bytes("SMC?STAT\u0002"));                // a version this side does not speak
        ask(bytes("SMC?STAT\u0001{\"x\":1}"));      // bytes after the version
        ask(bytes("SMC!STAT\u0001{}"));              // a reply sent to a cell is an ordinary datagram

        assertEquals(3, responder.malformed());
        assertEquals(0, responder.answered());
        assertEquals(List.of("127.0.0.1:4002 SMC!STAT\u0001{}"), cellGot);
        assertEquals(List.of(), askerGot);
    }

    @Test
    void oneFloodingSource_getsItsShareOnly_andOthersAreStillAnswered() {
        StatusResponder responder = new StatusResponder(cellSide, () -> VIEW, scheduler, 20, 4);
        Transport flooder = network.attach(Address.loopback(4666));
        List<byte[]> realAnswers = new ArrayList<>();
        for (int ms = 0; ms < 1_000; ms++) {   // 1,000 queries a second from one source
            flooder.send(cellSide.localAddress(), StatusResponder.query());
            if (ms % 100 == 50) {   // 10 real queries, from 10 tools
                Transport tool = network.attach(Address.loopback(5000 + ms));
                tool.setReceiver((from, data) -> realAnswers.add(data));
                tool.send(cellSide.localAddress(), StatusResponder.query());
            }
            scheduler.runUntil(scheduler.nowMillis() + 1);
        }
        scheduler.runUntilIdle(10_000);
        assertEquals(10, realAnswers.size(), "every real query answered");
        assertTrue(responder.answered() <= 10 + 4 + 4, "the flooder got its share only: " + responder.answered());
    }

    @Test
    void repliesOverTheRate_areRefusedAndCounted_untilASecondHasPassed() {
        StatusResponder responder = responder(() -> VIEW, 3);

        for (int i = 0; i < 5; i++) {
            asker.send(cellSide.localAddress(), StatusResponder.query());
        }
        scheduler.runUntilIdle(10_000);
        assertEquals(3, responder.answered());
        assertEquals(2, responder.refused());

        // The first reply's slot was taken when its query landed at 1 ms; each ask lands 1 ms after it is sent.
        scheduler.runUntil(999);
        ask(StatusResponder.query());          // lands at 1,000 ms: 999 ms after the first
        assertEquals(3, responder.refused());

        ask(StatusResponder.query());          // lands at 1,001 ms: a second after the first
        assertEquals(4, responder.answered());
        assertEquals(4, askerGot.size());
    }

    @Test
    void rateLimit_isASlidingSecond_notAFixedWindow() {
        StatusResponder responder = responder(() -> VIEW, 2);

        ask(StatusResponder.query());          // lands at 1 ms
        scheduler.runUntil(602);
        ask(StatusResponder.query());          // lands at 603 ms
        scheduler.runUntil(1_100);
        ask(StatusResponder.query());          // lands at 1,101 ms: the reply at 1 ms is over a second old
        ask(StatusResponder.query());          // lands at 1,103 ms: the reply at 603 ms is not

        assertEquals(3, responder.answered());
        assertEquals(1, responder.refused());
    }

    @Test
    void viewTooLargeForADatagram_isReplacedByAnErrorNamingItsSize() {
        String big = "{\"pad\":\"" + "x".repeat(2_000) + "\"}";
        StatusResponder responder = responder(() -> big, 20);

        ask(StatusResponder.query());

        assertEquals(List.of("{\"error\":\"status view too large\",\"bytes\":2010,\"limit\":1391}"), repliesAsJson());
        assertEquals(1, responder.answered());
    }

    @Test
    void viewOfExactlyTheLimit_fits() {
        String exact = "\"" + "y".repeat(StatusResponder.MAX_JSON_BYTES - 2) + "\"";
        responder(() -> exact, 20);

        ask(StatusResponder.query());

        assertEquals(List.of(exact), repliesAsJson());
        assertEquals(Transport.MAX_DATAGRAM_BYTES, askerGot.get(0).length);
    }

    @Test
    void viewThatFails_isAnsweredWithAnErrorObject() {
        responder(() -> {
            throw new IllegalStateException("not started");
        }, 20);

        ask(StatusResponder.query());

        assertEquals(List.of("{\"error\":\"status view failed\",\"exception\":\"java.lang.IllegalStateException\"}"),
                repliesAsJson());
    }

    @Test
    void datagramBeforeAReceiverIsSet_isDroppedAndCounted_butQueriesAreAnswered() {
        StatusResponder responder = new StatusResponder(cellSide, () -> VIEW, scheduler, 20);

        ask(bytes("early"));
        ask(StatusResponder.query());

        assertEquals(1, responder.droppedNoReceiver());
        assertEquals(List.of(VIEW), repliesAsJson());
    }

    @Test
    void secondReceiver_isRefused() {
        StatusResponder responder = responder();

        IllegalStateException e = assertThrows(IllegalStateException.class, () -> responder.setReceiver((f, d) -> { }));
        assertEquals("transport 127.0.0.1:4001 already has a receiver; it takes one", e.getMessage());
    }

    @Test
    void takesTheInnerTransportsReceiver() {
        responder();

        assertThrows(IllegalStateException.class, () -> cellSide.setReceiver((f, d) -> { }));
    }

    @Test
    void sendBroadcastAddressAndClose_goToTheInnerTransport() {
        StatusResponder responder = responder();
        List<String> heard = new ArrayList<>();
        Transport third = network.attach(Address.loopback(4003));
        third.setReceiver((from, data) -> heard.add(from + " " + new String(data, UTF_8)));

        responder.send(third.localAddress(), bytes("direct"));
        responder.broadcast(bytes("to all"));
        scheduler.runUntilIdle(10_000);
        responder.close();

        assertEquals(Address.loopback(4001), responder.localAddress());
        assertEquals(List.of("127.0.0.1:4001 direct", "127.0.0.1:4001 to all"), heard);
        assertEquals(1, askerGot.size(), "the asker heard the broadcast");
        assertThrows(IllegalStateException.class, () -> cellSide.send(third.localAddress(), bytes("x")), "inner is closed");
    }

    @Test
    void repliesPerSecond_mustBePositive() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new StatusResponder(cellSide, () -> VIEW, scheduler, 0));
        assertEquals("repliesPerSecond is 0; it must be 1 or more", e.getMessage());
    }

    @Test
    void replyJson_ofAnythingButAReply_isNull() {
        assertNull(StatusResponder.replyJson(StatusResponder.query(), 9));
        assertNull(StatusResponder.replyJson(bytes("SMC!STAT"), 8));
        assertNull(StatusResponder.replyJson(bytes("SMC!STAT\u0002{}"), 11));
        assertEquals("{}", StatusResponder.replyJson(bytes("SMC!STAT\u0001{}xx"), 11), "only the given length counts");
        assertTrue(StatusResponder.replyJson(bytes("SMC!STAT\u0001"), 9).isEmpty());
    }
}
