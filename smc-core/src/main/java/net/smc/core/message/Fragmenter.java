package net.smc.core.message;

import java.nio.ByteBuffer;
import net.smc.core.wire.ByteWriter;

/**
 * Splits a payload too large for one datagram into fragment frames, and holds the arithmetic that
 * the receiving side checks each frame against.
 *
 * <p>A payload of {@code total} bytes in {@code count} fragments is cut into chunks of
 * {@code ceil(total / count)} bytes, the last one taking the rest. The sender picks
 * {@code count = ceil(total / capacity)}, which keeps every chunk within a datagram and the last
 * one non-empty; the receiver needs no offsets, since index, count and total fix every chunk's
 * place and length.
 */
final class Fragmenter {
    private final int datagramLimit;
    /** The frame being written, and a view of it for sinks: made at the first fragmented message (most cells send none). */
    private byte[] datagram;
    private ByteBuffer view;

    /** A fragmenter whose frames are at most {@code datagramLimit} bytes long. */
    Fragmenter(int datagramLimit) {
        this.datagramLimit = datagramLimit;
    }

    /** Payload bytes one fragment frame can carry for a sender of {@code senderBytes}. */
    int capacity(int senderBytes) {
        return datagramLimit - Header.length(senderBytes) - WireFormat.FRAGMENT_HEADER;
    }

    /** How many fragments a payload of {@code total} bytes needs at {@code capacity} bytes each. */
    static int count(int total, int capacity) {
        return (total + capacity - 1) / capacity;
    }

    /** The length of the chunk at {@code index}, or 0 or less if these three cannot describe a valid split. */
    static int chunkLength(int index, int count, int total) {
        int chunk = chunkSize(count, total);
        return index < count - 1 ? chunk : total - (count - 1) * chunk;
    }

    /** Where the chunk at {@code index} starts in the payload. */
    static int offset(int index, int count, int total) {
        return index * chunkSize(count, total);
    }

    private static int chunkSize(int count, int total) {
        return (total + count - 1) / count;
    }

    /**
     * Writes the fragment frames of {@code payload[off, off+total)} one after the other into this
     * fragmenter's datagram buffer and hands each to {@code sink}. Returns how many were written.
     */
    int emit(byte[] payload, int off, int total, MessageType type, String sender, int senderBytes, long id,
            DatagramSink sink) {
        if (datagram == null) {
            datagram = new byte[datagramLimit];
            view = ByteBuffer.wrap(datagram).asReadOnlyBuffer();
        }
        int count = count(total, capacity(senderBytes));
        for (int i = 0; i < count; i++) {
            int len = chunkLength(i, count, total);
            int p = Header.write(datagram, 0, WireFormat.FRAGMENT_CODE, sender, senderBytes, id);
            datagram[p] = (byte) type.code();
            ByteWriter.putU16(datagram, p + 1, i);
            ByteWriter.putU16(datagram, p + 3, count);
            ByteWriter.putI32(datagram, p + 5, total);
            System.arraycopy(payload, off + offset(i, count, total), datagram, p + WireFormat.FRAGMENT_HEADER, len);
            view.clear().limit(p + WireFormat.FRAGMENT_HEADER + len);
            sink.datagram(view);
        }
        return count;
    }
}
