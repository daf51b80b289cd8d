package net.smc.core.comm;

import java.util.SplittableRandom;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;

import net.smc.core.message.CapabilityRequest;
import net.smc.core.message.MessageType;
import net.smc.core.router.MessageRouter;
import net.smc.core.transport.Address;
import net.smc.core.transport.real.RealTimeScheduler;
import net.smc.core.transport.real.SerialExecutor;
import net.smc.core.transport.real.SystemClock;
import net.smc.core.transport.udp.UdpEventLoop;
import net.smc.core.transport.udp.UdpSettings;
import net.smc.core.transport.udp.UdpTransport;

/**
 * Goal: at least 100,000 acknowledged critical messages per second between two cells over Netty
 * UDP on loopback. Cell A keeps {@code window} messages outstanding (a CAPABILITY_REQUEST, 30
 * bytes on the wire) and sends a new one each time one is acknowledged or given up on; cell B
 * acknowledges and dispatches each to a counting subscriber. Both cells run as deployed: their
 * own serial executor over a shared pool, a real-time scheduler, epoll where available. Prints
 * acknowledged messages per second over each measured second, then the mean, and both cells' counters.
 *
 * <pre>./gradlew :smc-core:jmh -PjmhMain=net.smc.core.comm.ReliableLoopbackThroughput -PjmhArgs="2000 3 10"</pre>
 * Measured on a 2-core VM: about 45,000-55,000 acknowledged messages/s (window 1,000-2,000) with one
 * sendmsg and one recvmsg per datagram and one cell task per datagram; about 95,000-101,000/s
 * (window 2,000, same session) since the UDP transport batches: one event-loop task and one flush
 * (sendmmsg) per burst of sends, up to 16 datagrams per recvmmsg, one cell task per read burst.
 * Each message is still two datagrams (the message and its Ack), all through the one Netty I/O
 * thread; coalescing Acks would halve that.
 * A second I/O thread does not help on two cores. A window much larger than timeout x rate
 * (e.g. 8,000) queues past the 200 ms initial timeout and causes spurious retransmissions.
 *
 * (arguments: window, warm-up seconds, measured seconds, cell pool threads (2), Netty I/O threads (1))
 */
public final class ReliableLoopbackThroughput {

    public static void main(String[] args) throws Exception {
        int window = args.length > 0 ? Integer.parseInt(args[0]) : 2_000;
        int warmupSeconds = args.length > 1 ? Integer.parseInt(args[1]) : 3;
        int seconds = args.length > 2 ? Integer.parseInt(args[2]) : 10;
        int poolThreads = args.length > 3 ? Integer.parseInt(args[3]) : 2;
        int ioThreads = args.length > 4 ? Integer.parseInt(args[4]) : 1;

        UdpEventLoop loop = UdpEventLoop.create(ioThreads);
        ExecutorService pool = Executors.newFixedThreadPool(poolThreads);
        ScheduledExecutorService timer = Executors.newSingleThreadScheduledExecutor();
        SystemClock clock = new SystemClock();
        UdpSettings udp = UdpSettings.defaults().withBroadcast("127.255.255.255", 47_999)
                .withReceiveBufferBytes(8 << 20);

        SerialExecutor cellA = new SerialExecutor(pool);
        SerialExecutor cellB = new SerialExecutor(pool);
        UdpTransport ta = UdpTransport.open(udp, cellA, loop);
        UdpTransport tb = UdpTransport.open(udp, cellB, loop);
        AtomicLong received = new AtomicLong();
        MessageRouter routerB = new MessageRouter();
        routerB.register(e -> received.incrementAndGet(), MessageType.CAPABILITY_REQUEST);
        CommunicationManager a = CommunicationManager.builder("uav-a", ta, clock, new RealTimeScheduler(timer, cellA))
                .random(new SplittableRandom(1)).router(new MessageRouter()).build();
        CommunicationManager b = CommunicationManager.builder("uav-b", tb, clock, new RealTimeScheduler(timer, cellB))
                .random(new SplittableRandom(2)).router(routerB).build();
        Address to = tb.localAddress();
        AtomicLong acked = new AtomicLong();
        AtomicLong failed = new AtomicLong();
        CapabilityRequest message = new CapabilityRequest("scout");

        DeliveryListener refill = new DeliveryListener() {
            @Override
            public void delivered(long id) {
                acked.incrementAndGet();
                a.send(to, message, this);
            }

            @Override
            public void failed(long id, FailureReason reason) {
                failed.incrementAndGet();
                a.send(to, message, this);
            }
        };
        CountDownLatch started = new CountDownLatch(2);
        cellB.execute(() -> {
            b.start();
            started.countDown();
        });
        cellA.execute(() -> {
            a.start();
            for (int i = 0; i < window; i++) {
                a.send(to, message, refill);
            }
            started.countDown();
        });
        started.await(10, TimeUnit.SECONDS);

        TimeUnit.SECONDS.sleep(warmupSeconds);
        long total = 0;
        long start = acked.get();
        long t0 = System.nanoTime();
        for (int s = 0; s < seconds; s++) {
            long before = acked.get();
            long n0 = System.nanoTime();
            TimeUnit.SECONDS.sleep(1);
            long rate = (acked.get() - before) * 1_000_000_000L / (System.nanoTime() - n0);
            System.out.printf("second %2d: %,d acked/s%n", s + 1, rate);
        }
        total = acked.get() - start;
        double mean = total * 1e9 / (System.nanoTime() - t0);
        System.out.printf("window %d, pool %d, io %d: mean %,.0f acknowledged messages/s (goal 100,000); failed %d%n",
                window, poolThreads, ioThreads, mean, failed.get());
        CountDownLatch stopped = new CountDownLatch(2);
        cellA.execute(() -> {
            System.out.println("A: " + a.sender().counters() + " | " + a.counters());
            a.stop();
            stopped.countDown();
        });
        cellB.execute(() -> {
            System.out.println("B: " + b.sender().counters() + " | " + b.counters() + " | dispatched " + received.get());
            b.stop();
            stopped.countDown();
        });
        stopped.await(10, TimeUnit.SECONDS);
        System.out.println("UDP A: " + ta.counters());
        System.out.println("UDP B: " + tb.counters());
        ta.close();
        tb.close();
        loop.close();
        timer.shutdownNow();
        pool.shutdownNow();
    }
}
