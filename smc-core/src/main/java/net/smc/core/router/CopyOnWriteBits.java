package net.smc.core.router;

import java.util.Arrays;

/**
 * Sets of subscriber slots as {@code long[]} bit sets, copy on write: changing one never changes
 * an array a dispatch in progress may be reading, so dispatch reads its arrays once and needs no
 * copies, and a subscriber may change registrations while it receives. Missing words read as 0,
 * so arrays are only as long as their highest bit needs.
 */
final class CopyOnWriteBits {
    static final long[] EMPTY = new long[0];

    private CopyOnWriteBits() {
    }

    static long word(long[] bits, int w) {
        return w < bits.length ? bits[w] : 0L;
    }

    static boolean has(long[] bits, int slot) {
        return (word(bits, slot >>> 6) & 1L << slot) != 0;
    }

    /** {@code bits} with {@code slot} set: the same array if it already was, else a new one. */
    static long[] with(long[] bits, int slot) {
        if (has(bits, slot)) {
            return bits;
        }
        int w = slot >>> 6;
        long[] copy = Arrays.copyOf(bits, Math.max(bits.length, w + 1));
        copy[w] |= 1L << slot;
        return copy;
    }

    /** {@code bits} without {@code slot}: the same array if it was not set, else a new one. */
    static long[] without(long[] bits, int slot) {
        if (!has(bits, slot)) {
            return bits;
        }
        long[] copy = bits.clone();
        copy[slot >>> 6] &= ~(1L << slot);
        int n = copy.length;
        while (n > 0 && copy[n - 1] == 0) {
            n--;
        }
        return n == 0 ? EMPTY : n == copy.length ? copy : Arrays.copyOf(copy, n);
    }

    /** {@code bits} with {@code slot} set or cleared. */
    static long[] set(long[] bits, int slot, boolean on) {
        return on ? with(bits, slot) : without(bits, slot);
    }

    static boolean isEmpty(long[] bits) {
        return bits.length == 0;
    }
}
