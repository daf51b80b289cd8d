package net.smc.core.transport.udp;

import static java.nio.charset.StandardCharsets.UTF_8;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import java.net.InetSocketAddress;
import java.util.List;

import io.netty.buffer.ByteBuf;
import io.netty.buffer.Unpooled;
import io.netty.channel.embedded.EmbeddedChannel;
import io.netty.channel.socket.DatagramPacket;

import net.smc.core.transport.QueueExecutor;
import net.smc.core.transport.Recorder;
import net.smc.core.transport.Signal;

import org.junit.jupiter.api.Test;

/** The inbound handler alone, on Netty's EmbeddedChannel: no sockets, no threads. */
class InboundHandlerTest {
    private static final InetSocketAddress SELF = new InetSocketAddress("127.0.0.1", 4001);
    private static final InetSocketAddress PEER = new InetSocketAddress("127.0.0.1", 4002);
    private static final InetSocketAddress HERE = new InetSocketAddress("0.0.0.0", 47_474);

    private final Signal signal = new Signal();
    private final QueueExecutor cell = new QueueExecutor(signal);
    private final UdpStats stats = new UdpStats();
    private final Inbox inbox = new Inbox(cell, stats);
    private final Recorder recorder = new Recorder(signal);
    private final EmbeddedChannel channel = new EmbeddedChannel(new InboundHandler(inbox, stats, SELF::equals));

    InboundHandlerTest() {
        inbox.setReceiver(recorder);
    }

    private static DatagramPacket packet(ByteBuf content, InetSocketAddress sender) {
        return new DatagramPacket(content, HERE, sender);
    }

    @Test
    void payload_isCopiedOut_andTheBufferReleased() {
        ByteBuf content = Unpooled.copiedBuffer("hello", UTF_8);

        assertFalse(channel.writeInbound(packet(content, PEER)), "nothing passes down the pipeline");

        assertEquals(0, content.refCnt());
        assertEquals(1, cell.runQueued(), "handed to the cell's executor, not run on the loop");
        assertEquals(List.of("127.0.0.1:4002 hello"), recorder.received());
        assertEquals(1, stats.delivered.sum());
    }

    @Test
    void readBurst_isOneTaskForTheCell_deliveredInOrder() {
        ByteBuf first = Unpooled.copiedBuffer("one", UTF_8);
        ByteBuf second = Unpooled.copiedBuffer("two", UTF_8);

        channel.writeInbound(packet(first, PEER), packet(second, PEER));   // then channelReadComplete

        assertEquals(0, first.refCnt());
        assertEquals(0, second.refCnt());
        assertEquals(1, cell.size(), "one task per read burst");
        cell.runQueued();
        assertEquals(List.of("127.0.0.1:4002 one", "127.0.0.1:4002 two"), recorder.received());
        assertEquals(2, stats.delivered.sum());
    }

    @Test
    void ownDatagram_isFilteredOut_andReleased() {
        ByteBuf content = Unpooled.copiedBuffer("echo", UTF_8);

        channel.writeInbound(packet(content, SELF));

        assertEquals(0, content.refCnt());
        assertEquals(0, cell.size());
        assertEquals(1, stats.ownBroadcastsFiltered.sum());
    }

    @Test
    void oversizeDatagram_isDropped_andReleased() {
        ByteBuf content = Unpooled.wrappedBuffer(new byte[1_401]);

        channel.writeInbound(packet(content, PEER));

        assertEquals(0, content.refCnt());
        assertEquals(0, cell.size());
        assertEquals(1, stats.droppedOversize.sum());
    }

    @Test
    void datagramQueuedBeforeClose_isNotDeliveredAfter() {
        channel.writeInbound(packet(Unpooled.copiedBuffer("late", UTF_8), PEER));

        inbox.close();
        cell.runQueued();

        assertEquals(0, recorder.count());
        assertEquals(1, stats.droppedClosed.sum());
    }

    @Test
    void datagram_beforeAReceiverIsSet_isCounted() {
        Inbox bare = new Inbox(cell, stats);
        EmbeddedChannel ch = new EmbeddedChannel(new InboundHandler(bare, stats, SELF::equals));

        ch.writeInbound(packet(Unpooled.copiedBuffer("early", UTF_8), PEER));
        cell.runQueued();

        assertEquals(1, stats.droppedNoReceiver.sum());
    }

    @Test
    void aRefusingExecutor_dropsAndCounts() {
        Inbox refused = new Inbox(task -> {
            throw new java.util.concurrent.RejectedExecutionException("shut down");
        }, stats);
        EmbeddedChannel ch = new EmbeddedChannel(new InboundHandler(refused, stats, SELF::equals));

        ch.writeInbound(packet(Unpooled.copiedBuffer("x", UTF_8), PEER));

        assertEquals(1, stats.droppedRejected.sum());
    }
}
