package net.smc.core.transport.udp;

import java.net.InetSocketAddress;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Predicate;

import io.netty.buffer.ByteBuf;
import io.netty.buffer.ByteBufUtil;
import io.netty.channel.ChannelHandlerContext;
import io.netty.channel.SimpleChannelInboundHandler;
import io.netty.channel.socket.DatagramPacket;

import net.smc.core.transport.Address;
import net.smc.core.transport.Transport;

import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Turns each arriving {@link DatagramPacket} into a byte array for the cell, on the event loop.
 *
 * <p>Buffer ownership: the packet (and its {@code ByteBuf}) belongs to this handler while
 * {@link #channelRead0} runs; {@link SimpleChannelInboundHandler} releases it when that method
 * returns. So the payload is copied out first, and nothing of the packet escapes the event loop.
 *
 * <p>The datagrams of one read burst are collected and handed to the cell as one task when Netty
 * signals the end of the burst ({@link #channelReadComplete}), in arrival order.
 */
final class InboundHandler extends SimpleChannelInboundHandler<DatagramPacket> {
    private static final Logger log = LoggerFactory.getLogger(InboundHandler.class);

    private final Inbox inbox;
    private final UdpStats stats;
    private final Predicate<InetSocketAddress> ownSender;
    /** Datagrams of the current read burst, handed to the cell together when the burst ends. */
    private List<Inbox.Datagram> burst = new ArrayList<>();

    /**
     * @param ownSender true for a sender that is this cell itself; its datagrams are dropped
     *                  (a cell's own broadcasts come back to its broadcast channel)
     */
    InboundHandler(Inbox inbox, UdpStats stats, Predicate<InetSocketAddress> ownSender) {
        super(DatagramPacket.class, true);
        this.inbox = inbox;
        this.stats = stats;
        this.ownSender = ownSender;
    }

    @Override
    protected void channelRead0(ChannelHandlerContext ctx, DatagramPacket packet) {
        InetSocketAddress sender = packet.sender();
        if (ownSender.test(sender)) {
            stats.ownBroadcastsFiltered.increment();
            return;
        }
        ByteBuf content = packet.content();
        if (content.readableBytes() > Transport.MAX_DATAGRAM_BYTES) {
            stats.droppedOversize.increment();
            log.debug("datagram of {} bytes or more from {} dropped: a datagram may carry at most {} bytes",
                    content.readableBytes(), sender, Transport.MAX_DATAGRAM_BYTES);
            return;
        }
        burst.add(new Inbox.Datagram(Address.of(sender), ByteBufUtil.getBytes(content)));
    }

    /** The end of a read burst (up to one {@code recvmmsg} or several reads): one task for the cell. */
    @Override
    public void channelReadComplete(ChannelHandlerContext ctx) {
        if (!burst.isEmpty()) {
            List<Inbox.Datagram> ready = burst;
            burst = new ArrayList<>();
            inbox.received(ready);
        }
        ctx.fireChannelReadComplete();
    }

    @Override
    public void exceptionCaught(ChannelHandlerContext ctx, Throwable cause) {
        log.debug("error on UDP channel {}; the channel stays open", ctx.channel().localAddress(), cause);
    }
}
