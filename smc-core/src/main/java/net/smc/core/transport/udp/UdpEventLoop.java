package net.smc.core.transport.udp;

import java.util.concurrent.TimeUnit;

import io.netty.bootstrap.Bootstrap;
import io.netty.channel.ChannelOption;
import io.netty.channel.EventLoopGroup;
import io.netty.channel.epoll.Epoll;
import io.netty.channel.epoll.EpollChannelOption;
import io.netty.channel.epoll.EpollDatagramChannel;
import io.netty.channel.epoll.EpollEventLoopGroup;
import io.netty.channel.nio.NioEventLoopGroup;
import io.netty.channel.socket.DatagramChannel;
import io.netty.channel.socket.InternetProtocolFamily;
import io.netty.channel.socket.nio.NioDatagramChannel;
import io.netty.util.concurrent.DefaultThreadFactory;

/**
 * The Netty threads that do the I/O of one or more {@link UdpTransport}s: epoll where the native
 * library loads, Java NIO elsewhere. Many cells in one JVM can share one loop; a transport opened
 * without one makes its own and closes it with itself. Only I/O runs here: datagrams are copied
 * and handed to each cell's executor, so a slow cell never stalls the loop.
 *
 * <p>Its threads are daemon threads named {@code smc-udp-*}: a loop left open does not keep the JVM alive.
 */
public final class UdpEventLoop implements AutoCloseable {
    private static final long SHUTDOWN_TIMEOUT_SECONDS = 5;

    private final EventLoopGroup group;
    private final boolean epoll;

    private UdpEventLoop(int threads, boolean epoll) {
        if (threads < 1) {
            throw new IllegalArgumentException("an event loop needs 1 thread or more, not " + threads);
        }
        DefaultThreadFactory threadFactory = new DefaultThreadFactory("smc-udp", true);
        this.epoll = epoll;
        this.group = epoll ? new EpollEventLoopGroup(threads, threadFactory) : new NioEventLoopGroup(threads, threadFactory);
    }

    /** A loop of {@code threads} threads, on epoll when {@link Epoll#isAvailable()}, on NIO otherwise. */
    public static UdpEventLoop create(int threads) {
        return new UdpEventLoop(threads, Epoll.isAvailable());
    }

    /** A loop on Java NIO even where epoll is available (portable behaviour; tests of the NIO path). */
    public static UdpEventLoop nio(int threads) {
        return new UdpEventLoop(threads, false);
    }

    /** Whether this loop uses the native epoll transport. */
    public boolean isEpoll() {
        return epoll;
    }

    /** Shuts the threads down, waiting up to {@value #SHUTDOWN_TIMEOUT_SECONDS} s. Closing again does nothing. */
    @Override
    public void close() {
        group.shutdownGracefully(0, SHUTDOWN_TIMEOUT_SECONDS, TimeUnit.SECONDS)
                .awaitUninterruptibly(SHUTDOWN_TIMEOUT_SECONDS + 1, TimeUnit.SECONDS);
    }

    boolean isShutDown() {
        return group.isShuttingDown();
    }

    /** A bootstrap for IPv4 datagram channels of this loop. */
    Bootstrap bootstrap() {
        return new Bootstrap().group(group).channelFactory(this::newChannel);
    }

    /** Lets several sockets of this host bind the same port, each receiving every broadcast. */
    void shareAddress(Bootstrap bootstrap) {
        bootstrap.option(ChannelOption.SO_REUSEADDR, true);
        if (epoll) {
            bootstrap.option(EpollChannelOption.SO_REUSEPORT, true);
        }
    }

    private DatagramChannel newChannel() {
        return epoll ? new EpollDatagramChannel(InternetProtocolFamily.IPv4)
                : new NioDatagramChannel(InternetProtocolFamily.IPv4);
    }
}
