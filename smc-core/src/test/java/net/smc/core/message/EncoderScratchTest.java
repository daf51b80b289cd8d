package net.smc.core.message;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.nio.ByteBuffer;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;

/**
 * The encoders of one thread share its scratch buffer: an encode begun inside another encode's sink
 * (a sink that sends again at once), or after one that failed, must still give every datagram its
 * own bytes, and encoders on other threads must not see each other's.
 */
class EncoderScratchTest {
    private static byte[] bytes(ByteBuffer d) {
        byte[] b = new byte[d.remaining()];
        d.duplicate().get(b);
        return b;
    }

    private static List<byte[]> alone(Envelope e) {
        return new MessageEncoder().datagrams(e);
    }

    private static void assertSame(List<byte[]> expected, List<byte[]> actual) {
        assertEquals(expected.size(), actual.size(), "datagrams");
        for (int i = 0; i < expected.size(); i++) {
            assertArrayEquals(expected.get(i), actual.get(i), "datagram " + i);
        }
    }

    @Test
    void anEncodeInsideAnotherEncodesSink_leavesTheOuterDatagramsAsTheyWere() {
        Envelope outer = new Envelope("uav-outer", 7, Samples.bulk("outer", 3_000)); // three fragments
        Envelope inner = new Envelope("uav-inner", 8, Samples.bulk("inner", 400));
        MessageEncoder first = new MessageEncoder();
        MessageEncoder second = new MessageEncoder();
        List<byte[]> seen = new ArrayList<>();
        List<byte[]> nested = new ArrayList<>();
        int n = first.encode(outer, d -> {
            byte[] before = bytes(d);
            second.encode(inner, in -> nested.add(bytes(in))); // another cell's send, on this thread
            assertArrayEquals(before, bytes(d), "the outer datagram is unchanged by the inner encode");
            seen.add(bytes(d));
        });
        assertEquals(seen.size(), n);
        assertSame(alone(outer), seen);
        assertEquals(n, nested.size());
        for (byte[] d : nested) {
            assertArrayEquals(alone(inner).get(0), d);
        }
    }

    @Test
    void aPayloadTooLargeForItsDatagram_leavesTheBufferFreeForTheNextEncode() {
        MessageEncoder encoder = new MessageEncoder();
        Envelope big = new Envelope("uav1", 1, Samples.bulk("big", 3_000));
        assertThrows(IllegalArgumentException.class, () -> encoder.encode(big, ByteBuffer.allocate(WireFormat.MAX_DATAGRAM)));
        Envelope small = new Envelope("uav1", 2, Samples.bulk("small", 100));
        ByteBuffer out = ByteBuffer.allocate(WireFormat.MAX_DATAGRAM);
        int size = encoder.encode(small, out);
        byte[] written = new byte[size];
        out.flip().get(written);
        assertArrayEquals(alone(small).get(0), written);
        assertSame(alone(big), encoder.datagrams(big));
    }

    @Test
    void encodersOnTwoThreadsAtOnce_eachGetTheirOwnBytes() throws Exception {
        ExecutorService pool = Executors.newFixedThreadPool(2);
        try {
            CountDownLatch bothInSinks = new CountDownLatch(2);
            List<Future<List<byte[]>>> results = new ArrayList<>();
            for (String who : List.of("uav-a", "uav-b")) {
                Envelope e = new Envelope(who, 1, Samples.bulk(who, 2_000));
                results.add(pool.submit(() -> {
                    List<byte[]> out = new ArrayList<>();
                    new MessageEncoder().encode(e, d -> {
                        if (out.isEmpty()) {
                            bothInSinks.countDown(); // both threads hold a scratch buffer at this moment
                            await(bothInSinks);
                        }
                        out.add(bytes(d));
                    });
                    return out;
                }));
            }
            assertSame(alone(new Envelope("uav-a", 1, Samples.bulk("uav-a", 2_000))), results.get(0).get(10, TimeUnit.SECONDS));
            assertSame(alone(new Envelope("uav-b", 1, Samples.bulk("uav-b", 2_000))), results.get(1).get(10, TimeUnit.SECONDS));
        } finally {
            pool.shutdownNow();
        }
    }

    private static void await(CountDownLatch latch) {
        try {
            if (!latch.await(10, TimeUnit.SECONDS)) {
                throw new IllegalStateException("the other thread never reached its sink");
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException(e);
        }
    }
}
