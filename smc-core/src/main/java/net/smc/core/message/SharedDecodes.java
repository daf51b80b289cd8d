package net.smc.core.message;

import java.util.Arrays;

/**
 * Decodes shared by the cells of one process that receive the same broadcast: a simulated team
 * delivers every discovery broadcast to each of its cells, and a thousand decoders reading the same
 * bytes make a thousand equal envelopes. With one of these given to every cell's decoder, the first
 * copy is decoded as usual and the others cost a hash and a byte comparison, and share the one
 * envelope (its strings, with their hashes, included).
 *
 * <p>Sound because decoding a whole datagram is a function of its bytes alone (fragments, which
 * depend on what arrived before, are never kept) and envelopes are immutable values. Only
 * {@link MessageType#DISCOVERY} datagrams are kept, the one message cells broadcast, so that the
 * unicast traffic pays nothing for it. A small direct-mapped table: a collision replaces the older
 * entry. Safe to share between threads, though one simulation uses it from one.
 */
public final class SharedDecodes {
    private static final int SLOTS = 64;

    private final byte[][] keys = new byte[SLOTS][];
    private final DecodeResult.Decoded[] values = new DecodeResult.Decoded[SLOTS];
    private long hits;
    private long misses;

    /** Whether a datagram whose header says {@code typeCode} is one this table keeps. */
    static boolean keeps(int typeCode) {
        return typeCode == MessageType.DISCOVERY.code();
    }

    /** The decode of exactly these bytes kept earlier, or null. */
    synchronized DecodeResult.Decoded find(byte[] data, int offset, int length) {
        int slot = slot(data, offset, length);
        byte[] key = keys[slot];
        if (key != null && Arrays.equals(key, 0, key.length, data, offset, offset + length)) {
            hits++;
            return values[slot];
        }
        misses++;
        return null;
    }

    /** Keeps {@code decoded} as the decode of these bytes. */
    synchronized void keep(byte[] data, int offset, int length, DecodeResult.Decoded decoded) {
        int slot = slot(data, offset, length);
        keys[slot] = Arrays.copyOfRange(data, offset, offset + length);
        values[slot] = decoded;
    }

    /** Look-ups answered from the table. */
    public synchronized long hits() {
        return hits;
    }

    /** Look-ups that had to decode. */
    public synchronized long misses() {
        return misses;
    }

    /**
     * The slot of a datagram, from its length, the sender's length and last bytes and the message
     * id, which tell one sender's datagrams apart (the header: magic, version, type, sender length,
     * sender, id); the whole datagram is compared on a hit.
     */
    private static int slot(byte[] data, int offset, int length) {
        int h = length;
        int senderLength = data[offset + 4] & 0xFF;
        int idAt = offset + 5 + senderLength;
        if (idAt + 8 > offset + length) {
            return h & SLOTS - 1; // not a whole header: the decoder rejects it
        }
        for (int i = idAt - Math.min(2, senderLength); i < idAt + 8; i++) {
            h = 31 * h + data[i];
        }
        return (h ^ h >>> 16) & SLOTS - 1;
    }
}
