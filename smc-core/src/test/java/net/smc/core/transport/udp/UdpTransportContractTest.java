package net.smc.core.transport.udp;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.function.BooleanSupplier;

import net.smc.core.transport.Transport;
import net.smc.core.transport.TransportContract;

/**
 * The transport contract on real UDP over loopback, on epoll. Callbacks go to a four-thread pool,
 * so the one-call-at-a-time rule is really tested. Each run broadcasts on a port of its own, so
 * other runs on the machine do not cross its path.
 */
class UdpTransportContractTest extends TransportContract {
    /** A hang guard for real datagrams, not a speed check: loopback delivers in microseconds. */
    static final long AWAIT_MILLIS = 10_000;

    UdpEventLoop newLoop() {
        UdpEventLoop loop = UdpEventLoop.create(2);
        assertTrue(loop.isEpoll(), "epoll expected on this machine");
        return loop;
    }

    @Override
    protected Net newNet() {
        UdpEventLoop loop = newLoop();
        ExecutorService pool = Executors.newFixedThreadPool(4);
        UdpSettings settings = UdpSettings.defaults().withBroadcast("127.255.255.255", FreePort.udp());
        return new Net() {
            private final List<Transport> opened = new ArrayList<>();

            @Override
            public Transport open() {
                try {
                    Transport t = UdpTransport.open(settings, pool, loop);
                    opened.add(t);
                    return t;
                } catch (IOException e) {
                    throw new UncheckedIOException(e);
                }
            }

            @Override
            public void awaitUntil(BooleanSupplier done) {
                try {
                    assertTrue(signal.await(done, AWAIT_MILLIS), "datagrams did not arrive within " + AWAIT_MILLIS + " ms");
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    fail("interrupted while waiting for datagrams");
                }
            }

            @Override
            public void close() {
                opened.forEach(Transport::close);
                loop.close();
                pool.shutdownNow();
            }
        };
    }
}
