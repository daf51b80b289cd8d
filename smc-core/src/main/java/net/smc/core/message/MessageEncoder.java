package net.smc.core.message;

import java.nio.ByteBuffer;
import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import java.util.Set;
import net.smc.core.wire.ByteWriter;

/**
 * Turns an {@link Envelope} into datagrams in the <a href="doc-files/wire-format.md">wire format</a>:
 * into a caller's reusable buffer when it fits one datagram (heartbeats, acks: the hot path, which
 * allocates nothing), or into as many fragment frames as its payload needs.
 *
 * <p>The payload is written first into a scratch buffer, behind room for the largest header, and
 * the header is then put in front of it, so that a single datagram is one contiguous copy. The
 * buffer (about 64 KiB, room for the largest payload) belongs to the thread, not to the encoder:
 * the encoders of a thousand simulated cells on one thread share one, instead of each holding 64
 * KiB of which a heartbeat touches a hundred bytes. An encode that starts while another on the
 * same thread still has the buffer (a sink that sends again at once) gets a buffer of its own. An
 * encoder is not thread-safe (its counters): one per cell, used on the cell's thread.
 *
 * <p>Every header names its sender unless told otherwise: a cell whose transport proves who sent
 * each datagram leaves the sender of the types it chooses to that transport
 * ({@link #leaveSenderToTransport}), and its receivers take the sender their transport proves.
 */
public final class MessageEncoder {
    /** Room for the largest header in front of the payload. */
    private static final int HEADROOM = Header.length(WireFormat.MAX_SENDER);

    /** The thread's scratch buffer, shared by every encoder that runs on the thread. */
    private static final ThreadLocal<Scratch> SCRATCH = ThreadLocal.withInitial(Scratch::new);

    private final int datagramLimit;
    private final Fragmenter fragmenter;
    /** The types whose header leaves the sender to the transport. */
    private final Set<MessageType> senderLeft = EnumSet.noneOf(MessageType.class);
    /** The scratch of the thread this encoder last ran on: found again without the thread-local's look-up. */
    private Scratch recent;
    private long messages;
    private long datagrams;
    private long fragmented;

    /** An encoder whose datagrams are at most {@link WireFormat#MAX_DATAGRAM} bytes long. */
    public MessageEncoder() {
        this(WireFormat.MAX_DATAGRAM);
    }

    /**
     * An encoder whose datagrams are at most {@code datagramLimit} bytes long: the capacity of the
     * transport it feeds, once that has taken its own envelope off {@link WireFormat#MAX_DATAGRAM}.
     *
     * @throws IllegalArgumentException if the limit leaves no room for a fragment of the longest sender's message
     */
    public MessageEncoder(int datagramLimit) {
        int least = Header.length(WireFormat.MAX_SENDER) + WireFormat.FRAGMENT_HEADER + 64;
        if (datagramLimit < least || datagramLimit > WireFormat.MAX_DATAGRAM) {
            throw new IllegalArgumentException("a datagram limit of " + datagramLimit + " bytes; it must be from "
                    + least + " to " + WireFormat.MAX_DATAGRAM);
        }
        this.datagramLimit = datagramLimit;
        this.fragmenter = new Fragmenter(datagramLimit);
    }

    /**
     * Leaves the sender of messages of {@code types} out of their headers, to be named by the
     * transport on the receiving side (sender length 0 in <a href="doc-files/wire-format.md">the
     * wire format</a>); the other types still name it. For an authenticating transport, whose
     * receivers take the proven sender from it: a receiver with none refuses such a datagram, so
     * leave out only what is read after the transport has proven its sender.
     *
     * @return this encoder
     */
    public MessageEncoder leaveSenderToTransport(Set<MessageType> types) {
        senderLeft.clear();
        senderLeft.addAll(types);
        return this;
    }

    /**
     * Encodes a message that fits one datagram into {@code out}, from its position, and advances
     * the position past it.
     *
     * @return the datagram's length
     * @throws IllegalArgumentException if the message needs fragments (use {@link #encode(Envelope, DatagramSink)}),
     *                                  if its payload is over {@link WireFormat#MAX_PAYLOAD}, or if {@code out}
     *                                  has too little room
     */
    public int encode(Envelope envelope, ByteBuffer out) {
        Scratch scratch = acquire();
        try {
            String sender = named(envelope);
            int senderBytes = sender == null ? 0 : Utf8.length(sender);
            int payload = writePayload(scratch, envelope);
            int headerLength = Header.length(senderBytes);
            int size = headerLength + payload;
            if (size > datagramLimit) {
                throw new IllegalArgumentException(describe(envelope) + ": its payload of " + payload
                        + " bytes needs fragments (one datagram holds " + (datagramLimit - headerLength)
                        + " payload bytes for this sender); use encode(envelope, sink)");
            }
            if (out.remaining() < size) {
                throw new IllegalArgumentException(describe(envelope) + ": the buffer has " + out.remaining()
                        + " bytes left; the datagram needs " + size);
            }
            int start = HEADROOM - headerLength;
            Header.write(scratch.bytes, start, envelope.type().code(), sender, senderBytes, envelope.id());
            out.put(scratch.bytes, start, size);
            messages++;
            datagrams++;
            return size;
        } finally {
            scratch.release();
        }
    }

    /**
     * Encodes a message of any size into one datagram, or into fragment frames when its payload
     * exceeds one datagram, and hands each to {@code sink} in order.
     *
     * @return how many datagrams the sink received
     * @throws IllegalArgumentException if the payload is over {@link WireFormat#MAX_PAYLOAD}
     */
    public int encode(Envelope envelope, DatagramSink sink) {
        Scratch scratch = acquire();
        try {
            String sender = named(envelope);
            int senderBytes = sender == null ? 0 : Utf8.length(sender);
            int payload = writePayload(scratch, envelope);
            int headerLength = Header.length(senderBytes);
            messages++;
            if (headerLength + payload <= datagramLimit) {
                int start = HEADROOM - headerLength;
                Header.write(scratch.bytes, start, envelope.type().code(), sender, senderBytes, envelope.id());
                scratch.view.clear().position(start).limit(start + headerLength + payload);
                datagrams++;
                sink.datagram(scratch.view);
                return 1;
            }
            fragmented++;
            int n = fragmenter.emit(scratch.bytes, HEADROOM, payload, envelope.type(), sender, senderBytes,
                    envelope.id(), sink);
            datagrams += n;
            return n;
        } finally {
            scratch.release();
        }
    }

    /** Encodes a message into fresh arrays, one per datagram: for tests and occasional senders. */
    public List<byte[]> datagrams(Envelope envelope) {
        List<byte[]> out = new ArrayList<>(1);
        encode(envelope, d -> {
            byte[] b = new byte[d.remaining()];
            d.get(b);
            out.add(b);
        });
        return out;
    }

    /** Messages encoded so far. */
    public long messages() {
        return messages;
    }

    /** Datagrams written so far, fragment frames included. */
    public long datagrams() {
        return datagrams;
    }

    /** Messages that needed fragments. */
    public long fragmentedMessages() {
        return fragmented;
    }

    /** The sender the header names, or null when it is left to the transport. */
    private String named(Envelope envelope) {
        return senderLeft.contains(envelope.type()) ? null : envelope.sender();
    }

    /** The thread's scratch, lent to this encode; a fresh one if it is lent already. */
    private Scratch acquire() {
        Scratch own = recent;
        if (own == null || own.owner != Thread.currentThread()) {
            own = SCRATCH.get();
            recent = own;
        }
        if (own.lent) {
            return new Scratch();
        }
        own.lent = true;
        return own;
    }

    private static int writePayload(Scratch scratch, Envelope envelope) {
        ByteWriter writer = scratch.writer;
        writer.reset(HEADROOM, scratch.bytes.length);
        try {
            BodyCodec.of(envelope.type()).write(envelope.body(), writer);
        } catch (PayloadOverflow e) {
            throw new IllegalArgumentException(describe(envelope) + ": its payload exceeds " + WireFormat.MAX_PAYLOAD
                    + " bytes, the limit of one message");
        }
        return writer.position() - HEADROOM;
    }

    /**
     * A payload's scratch buffer, with a view of it for sinks and a writer over it. The thread's own is
     * lent to one encode at a time; an encode that finds it lent (one started from inside another's
     * sink) gets a fresh one, so no encode ever writes into bytes a sink is still reading.
     */
    private static final class Scratch {
        final byte[] bytes = new byte[HEADROOM + WireFormat.MAX_PAYLOAD];
        final ByteBuffer view = ByteBuffer.wrap(bytes).asReadOnlyBuffer();
        final ByteWriter writer = new ByteWriter(bytes, () -> PayloadOverflow.INSTANCE);
        /** The thread that made it: a thread's own is used on that thread only. */
        final Thread owner = Thread.currentThread();
        /** Whether it is lent to an encode now. */
        private boolean lent;

        void release() {
            lent = false;
        }
    }

    /** Thrown by the writer when a payload does not fit; carries nothing, so one instance serves. */
    private static final class PayloadOverflow extends RuntimeException {
        private static final long serialVersionUID = 1L;
        static final PayloadOverflow INSTANCE = new PayloadOverflow();

        private PayloadOverflow() {
            super("payload overflow", null, false, false);
        }
    }

    private static String describe(Envelope e) {
        return e.type() + " from '" + e.sender() + "' (id " + e.id() + ")";
    }
}
