package net.smc.core.comm;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.DatagramSocket;
import java.net.InetSocketAddress;
import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.SplittableRandom;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;

import net.smc.core.transport.Signal;
import net.smc.core.transport.Transport;
import net.smc.core.transport.real.RealTimeScheduler;
import net.smc.core.transport.real.SerialExecutor;
import net.smc.core.transport.real.SystemClock;
import net.smc.core.transport.udp.UdpEventLoop;
import net.smc.core.transport.udp.UdpSettings;
import net.smc.core.transport.udp.UdpTransport;

/**
 * Cells on Netty UDP over loopback, each on its own serial executor with a real-time scheduler.
 * Faults come from a {@link FaultyTransport} around each cell's transport. Waits are bounded
 * latches (hang guards), never sleeps.
 */
final class UdpNet implements Net {
    static final long HANG_GUARD_MILLIS = 10_000;

    private final Faults faults;
    private final SplittableRandom seeds;
    private final SenderSettings settings;
    private final UdpEventLoop loop = UdpEventLoop.create(2);
    private final ExecutorService pool = Executors.newFixedThreadPool(4);
    private final ScheduledExecutorService timer = Executors.newSingleThreadScheduledExecutor();
    private final SystemClock clock = new SystemClock();
    private final Signal signal = new Signal();
    private final UdpSettings udp = UdpSettings.defaults().withBroadcast("127.255.255.255", freePort());
    private final Map<Peer, SerialExecutor> executors = new IdentityHashMap<>();
    private final Map<Peer, Transport> transports = new IdentityHashMap<>();
    private final List<Peer> peers = new ArrayList<>();

    UdpNet(Faults faults, long seed, SenderSettings settings) {
        this.faults = faults;
        this.seeds = new SplittableRandom(seed);
        this.settings = settings;
    }

    @Override
    public Peer peer(String vehicleId) {
        SerialExecutor cell = new SerialExecutor(pool);
        try {
            Transport transport = new FaultyTransport(UdpTransport.open(udp, cell, loop), seeds.nextLong(),
                    faults.loss(), faults.duplication(), faults.reorder());
            var builder = CommunicationManager.builder(vehicleId, transport, clock, new RealTimeScheduler(timer, cell))
                    .random(seeds.split()).settings(settings);
            Peer[] made = new Peer[1];
            run(cell, () -> made[0] = new Peer(builder, clock, signal));
            synchronized (this) {
                executors.put(made[0], cell);
                transports.put(made[0], transport);
                peers.add(made[0]);
            }
            return made[0];
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    @Override
    public void onCell(Peer peer, Runnable action) {
        run(executors.get(peer), action);
    }

    @Override
    public void awaitUntil(BooleanSupplier done, long withinMillis) {
        try {
            assertTrue(signal.await(done, Math.max(withinMillis, HANG_GUARD_MILLIS)),
                    "not done within " + Math.max(withinMillis, HANG_GUARD_MILLIS) + " ms");
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            fail("interrupted while waiting");
        }
    }

    @Override
    public void makeUnreachable(Peer peer) {
        onCell(peer, () -> {
            peer.manager.stop();
            transports.get(peer).close();
        });
    }

    @Override
    public long slackMillis() {
        return 250;
    }

    @Override
    public void close() {
        for (Peer p : peers) {
            onCell(p, () -> {
                p.manager.stop();
                transports.get(p).close();
            });
        }
        loop.close();
        timer.shutdownNow();
        pool.shutdownNow();
    }

    private static void run(SerialExecutor cell, Runnable action) {
        CountDownLatch done = new CountDownLatch(1);
        RuntimeException[] thrown = new RuntimeException[1];
        cell.execute(() -> {
            try {
                action.run();
            } catch (RuntimeException e) {
                thrown[0] = e;
            } finally {
                done.countDown();
            }
        });
        try {
            assertTrue(done.await(HANG_GUARD_MILLIS, TimeUnit.MILLISECONDS), "cell task did not run within "
                    + HANG_GUARD_MILLIS + " ms");
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            fail("interrupted while waiting for a cell task");
        }
        if (thrown[0] != null) {
            throw thrown[0];
        }
    }

    private static int freePort() {
        try (DatagramSocket probe = new DatagramSocket(new InetSocketAddress("0.0.0.0", 0))) {
            return probe.getLocalPort();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
