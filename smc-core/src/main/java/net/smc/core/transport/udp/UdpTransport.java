package net.smc.core.transport.udp;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.NetworkInterface;
import java.util.Collections;
import java.util.Objects;
import java.util.Queue;
import java.util.Set;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.Executor;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.function.Predicate;
import java.util.stream.Collectors;

import io.netty.bootstrap.Bootstrap;
import io.netty.buffer.ByteBuf;
import io.netty.channel.Channel;
import io.netty.channel.ChannelFuture;
import io.netty.channel.ChannelFutureListener;
import io.netty.channel.ChannelOption;
import io.netty.channel.FixedRecvByteBufAllocator;
import io.netty.channel.epoll.EpollChannelOption;
import io.netty.channel.socket.DatagramPacket;

import net.smc.core.transport.Address;
import net.smc.core.transport.DatagramTooLargeException;
import net.smc.core.transport.Receiver;
import net.smc.core.transport.Transport;
import net.smc.core.transport.real.SerialExecutor;

import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A cell's endpoint on real UDP, over Netty. Two channels: the cell's own unicast channel (bound on
 * {@link UdpSettings#bindHost()}:{@link UdpSettings#port()}, which also sends the broadcasts, so
 * every datagram carries the address a reply should go to), and a broadcast channel bound on
 * {@code 0.0.0.0}:{@link UdpSettings#broadcastPort()} with SO_REUSEADDR (and SO_REUSEPORT on
 * epoll), which every cell of the host shares and which gets every broadcast, the cell's own
 * included; those are filtered out here.
 *
 * <p>Threading: datagrams are read on the {@link UdpEventLoop}, copied out of Netty's buffers and
 * handed to the executor given at open (the cell's executor), through a {@link SerialExecutor} so
 * the receiver runs one call at a time even on a thread pool. No cell code runs on the event loop.
 * The send methods may be called from any thread; they copy the data before returning.
 *
 * <p>Buffer ownership: a send copies the caller's array into a {@code ByteBuf} that passes to Netty
 * with the write, and Netty releases it once written or failed; inbound buffers belong to
 * {@link InboundHandler}, which releases them.
 *
 * <p>See <a href="../doc-files/transport.md">the transport design note</a>.
 */
public final class UdpTransport implements Transport {
    private static final Logger log = LoggerFactory.getLogger(UdpTransport.class);
    private static final long CHANNEL_TIMEOUT_SECONDS = 10;
    /** Larger than any legal datagram, so an oversize one shows up as such instead of being cut silently. */
    private static final int READ_BUFFER_BYTES = 2048;
    /** Datagrams one epoll read system call may take ({@code recvmmsg}). */
    private static final int DATAGRAMS_PER_READ = 16;

    private final UdpSettings settings;
    private final UdpEventLoop loop;
    private final boolean ownsLoop;
    private final UdpStats stats;
    private final Inbox inbox;
    private final Channel unicast;
    private final Channel broadcastChannel;
    private final Address localAddress;
    private final InetSocketAddress broadcastTarget;
    private final AtomicBoolean closed = new AtomicBoolean();
    private final ChannelFutureListener countFailure;
    /** Datagrams sent but not yet handed to the channel; drained on the event loop by {@link #drain}. */
    private final Queue<DatagramPacket> outbox = new ConcurrentLinkedQueue<>();
    /** Whether a drain is queued on the event loop and has not started yet. */
    private final AtomicBoolean drainQueued = new AtomicBoolean();
    private final Runnable drain = this::drain;

    private UdpTransport(UdpSettings settings, UdpEventLoop loop, boolean ownsLoop, UdpStats stats, Inbox inbox,
                         Channel unicast, Channel broadcastChannel, Address localAddress, InetSocketAddress broadcastTarget) {
        this.settings = settings;
        this.loop = loop;
        this.ownsLoop = ownsLoop;
        this.stats = stats;
        this.inbox = inbox;
        this.unicast = unicast;
        this.broadcastChannel = broadcastChannel;
        this.localAddress = localAddress;
        this.broadcastTarget = broadcastTarget;
        this.countFailure = future -> {
            if (!future.isSuccess()) {
                stats.sendFailures.increment();
                log.debug("send from {} failed", localAddress, future.cause());
            }
        };
    }

    /**
     * Opens a transport with an event loop of its own (one thread), closed with it.
     *
     * @param cellExecutor where the receiver runs: the cell's executor
     * @throws IOException when a channel cannot be bound (the port is taken, the host is not local)
     */
    public static UdpTransport open(UdpSettings settings, Executor cellExecutor) throws IOException {
        UdpEventLoop loop = UdpEventLoop.create(1);
        try {
            return open(settings, cellExecutor, loop, true);
        } catch (IOException | RuntimeException e) {
            loop.close();
            throw e;
        }
    }

    /**
     * Opens a transport on a shared event loop, which stays open when the transport closes.
     *
     * @param cellExecutor where the receiver runs: the cell's executor
     * @throws IOException when a channel cannot be bound (the port is taken, the host is not local)
     */
    public static UdpTransport open(UdpSettings settings, Executor cellExecutor, UdpEventLoop loop) throws IOException {
        return open(settings, cellExecutor, loop, false);
    }

    private static UdpTransport open(UdpSettings settings, Executor cellExecutor, UdpEventLoop loop, boolean ownsLoop)
            throws IOException {
        Objects.requireNonNull(settings, "settings");
        Objects.requireNonNull(cellExecutor, "cellExecutor");
        if (Objects.requireNonNull(loop, "loop").isShutDown()) {
            throw new IllegalStateException("the UDP event loop is closed; a transport cannot open on it");
        }
        InetSocketAddress broadcastTarget = new InetSocketAddress(ipv4(settings.broadcastHost()), settings.broadcastPort());
        UdpStats stats = new UdpStats();
        Executor serial = cellExecutor instanceof SerialExecutor ? cellExecutor : new SerialExecutor(cellExecutor);
        Inbox inbox = new Inbox(serial, stats);

        Bootstrap unicastBootstrap = bootstrap(loop, settings)
                .option(ChannelOption.SO_BROADCAST, true)
                .handler(new InboundHandler(inbox, stats, sender -> false));   // a unicast to oneself is delivered
        Channel unicast = bind(unicastBootstrap, settings.bindHost(), settings.port(), "unicast");
        int port = ((InetSocketAddress) unicast.localAddress()).getPort();
        Address local = Address.of(settings.reachableHost(), port);

        Channel broadcast;
        try {
            Bootstrap broadcastBootstrap = bootstrap(loop, settings)
                    .handler(new InboundHandler(inbox, stats, ownSender(settings, port)));
            loop.shareAddress(broadcastBootstrap);
            broadcast = bind(broadcastBootstrap, UdpSettings.WILDCARD, settings.broadcastPort(), "broadcast");
        } catch (IOException | RuntimeException e) {
            unicast.close().awaitUninterruptibly(CHANNEL_TIMEOUT_SECONDS, TimeUnit.SECONDS);
            throw e;
        }
        log.debug("UDP transport {} open (broadcast {}:{}, {})", local, settings.broadcastHost(),
                settings.broadcastPort(), loop.isEpoll() ? "epoll" : "nio");
        return new UdpTransport(settings, loop, ownsLoop, stats, inbox, unicast, broadcast, local, broadcastTarget);
    }

    @Override
    public Address localAddress() {
        return localAddress;
    }

    /** The settings this transport was opened with. */
    public UdpSettings settings() {
        return settings;
    }

    /** What this transport has done so far. */
    public UdpCounters counters() {
        return stats.snapshot();
    }

    @Override
    public void send(Address to, byte[] data) {
        Objects.requireNonNull(to, "to");
        checkCanSend(to, data);
        write(to.toInetSocketAddress(), data);
        stats.sent.increment();
    }

    @Override
    public void broadcast(byte[] data) {
        checkCanSend(null, data);
        write(broadcastTarget, data);
        stats.broadcastsSent.increment();
    }

    @Override
    public void setReceiver(Receiver receiver) {
        Objects.requireNonNull(receiver, "receiver");
        if (!inbox.setReceiver(receiver)) {
            throw new IllegalStateException("transport " + localAddress + " already has a receiver; it takes one");
        }
    }

    /**
     * Picks the datagrams the cell gets first: those {@code urgent} accepts (called on the event
     * loop, for every datagram: it must be cheap, e.g. look at a kind byte) are delivered before any
     * other; the others wait in a bounded queue and are dropped (counted as {@code droppedBacklog})
     * when it is full. Until this is called every datagram is urgent, in one unbounded lane.
     */
    public void setUrgent(java.util.function.Predicate<byte[]> urgent) {
        inbox.setUrgent(Objects.requireNonNull(urgent, "urgent"));
    }

    /** Closes both channels and, if this transport made it, its event loop. Closing again does nothing. */
    @Override
    public void close() {
        if (!closed.compareAndSet(false, true)) {
            return;
        }
        inbox.close();
        ChannelFuture a = unicast.close();
        ChannelFuture b = broadcastChannel.close();
        a.awaitUninterruptibly(CHANNEL_TIMEOUT_SECONDS, TimeUnit.SECONDS);
        b.awaitUninterruptibly(CHANNEL_TIMEOUT_SECONDS, TimeUnit.SECONDS);
        if (ownsLoop) {
            loop.close();
        }
        discardOutbox();   // a send that raced with close and found no loop to drain it
        log.debug("UDP transport {} closed", localAddress);
    }

    UdpEventLoop loop() {
        return loop;
    }

    @Override
    public String toString() {
        return "UdpTransport[" + localAddress + (closed.get() ? ", closed]" : "]");
    }

    private void checkCanSend(Address to, byte[] data) {
        Objects.requireNonNull(data, "data");
        if (closed.get()) {
            throw new IllegalStateException("transport " + localAddress + " is closed; it cannot send");
        }
        try {
            DatagramTooLargeException.check(localAddress, to, data.length);
        } catch (DatagramTooLargeException e) {
            stats.refusedOversize.increment();
            throw e;
        }
    }

    /**
     * Queues the datagram and, unless a drain is already queued, queues one on the event loop. So
     * a burst of sends from the cell costs one task and one wake-up of the loop, and the drain
     * writes the whole burst before one flush, which on epoll goes out in one {@code sendmmsg}.
     */
    private void write(InetSocketAddress target, byte[] data) {
        ByteBuf buffer = unicast.alloc().buffer(data.length).writeBytes(data);   // Netty releases it after the write
        outbox.add(new DatagramPacket(buffer, target));
        if (drainQueued.compareAndSet(false, true)) {
            try {
                unicast.eventLoop().execute(drain);
            } catch (RuntimeException e) {   // the loop is shutting down: nothing will write these
                drainQueued.set(false);
                discardOutbox();
                throw e;
            }
        }
    }

    /**
     * On the event loop: writes every queued datagram, then flushes once. The flag is cleared
     * before the queue is read, so a datagram queued meanwhile is either written here or queues a
     * drain of its own; none is left behind.
     */
    private void drain() {
        drainQueued.set(false);
        DatagramPacket packet;
        boolean wrote = false;
        while ((packet = outbox.poll()) != null) {
            unicast.write(packet).addListener(countFailure);
            wrote = true;
        }
        if (wrote) {
            unicast.flush();
        }
    }

    private void discardOutbox() {
        DatagramPacket packet;
        while ((packet = outbox.poll()) != null) {
            packet.release();
            stats.sendFailures.increment();
        }
    }

    /**
     * On epoll, each read takes up to {@value #DATAGRAMS_PER_READ} datagrams in one {@code recvmmsg}
     * (each in its own {@value #READ_BUFFER_BYTES}-byte slot of one buffer); on NIO, one per read.
     */
    private static Bootstrap bootstrap(UdpEventLoop loop, UdpSettings settings) {
        Bootstrap b = loop.bootstrap().option(ChannelOption.SO_RCVBUF, settings.receiveBufferBytes());
        if (loop.isEpoll()) {
            return b.option(EpollChannelOption.MAX_DATAGRAM_PAYLOAD_SIZE, READ_BUFFER_BYTES)
                    .option(ChannelOption.RCVBUF_ALLOCATOR, new FixedRecvByteBufAllocator(READ_BUFFER_BYTES * DATAGRAMS_PER_READ));
        }
        return b.option(ChannelOption.RCVBUF_ALLOCATOR, new FixedRecvByteBufAllocator(READ_BUFFER_BYTES));
    }

    private static Channel bind(Bootstrap bootstrap, String host, int port, String role) throws IOException {
        ChannelFuture bound = bootstrap.bind(new InetSocketAddress(ipv4(host), port));
        if (!bound.awaitUninterruptibly(CHANNEL_TIMEOUT_SECONDS, TimeUnit.SECONDS)) {
            bound.channel().close();
            throw new IOException("cannot bind the " + role + " channel on " + host + ":" + port + ": no answer within "
                    + CHANNEL_TIMEOUT_SECONDS + " s");
        }
        if (!bound.isSuccess()) {
            Throwable cause = bound.cause();
            throw new IOException("cannot bind the " + role + " channel on " + host + ":" + port + ": " + cause.getMessage(), cause);
        }
        return bound.channel();
    }

    /** Whether a datagram's sender is this cell: its unicast port on one of its own addresses. */
    private static Predicate<InetSocketAddress> ownSender(UdpSettings settings, int port) throws IOException {
        Set<InetAddress> own = settings.bindHost().equals(UdpSettings.WILDCARD)
                ? localInterfaceAddresses()
                : Set.of(ipv4(settings.bindHost()));
        return sender -> sender.getPort() == port && own.contains(sender.getAddress());
    }

    private static Set<InetAddress> localInterfaceAddresses() throws IOException {
        return Collections.list(NetworkInterface.getNetworkInterfaces()).stream()
                .flatMap(NetworkInterface::inetAddresses)
                .collect(Collectors.toUnmodifiableSet());
    }

    /** A validated IPv4 literal as an address; a literal needs no name lookup. */
    private static InetAddress ipv4(String literal) throws IOException {
        return InetAddress.getByName(literal);
    }
}
