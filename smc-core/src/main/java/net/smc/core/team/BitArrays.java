package net.smc.core.team;

/** The few operations the planner needs on bitsets kept as {@code long[]}. */
final class BitArrays {
    private BitArrays() {
    }

    static boolean get(long[] bits, int i) {
        return (bits[i >>> 6] & 1L << i) != 0;
    }

    static void set(long[] bits, int i) {
        bits[i >>> 6] |= 1L << i;
    }

    static void clear(long[] bits, int i) {
        bits[i >>> 6] &= ~(1L << i);
    }

    static int count(long[] bits) {
        int n = 0;
        for (long word : bits) {
            n += Long.bitCount(word);
        }
        return n;
    }

    /** The index of the first set bit at or after {@code from}, or -1. */
    static int next(long[] bits, int from) {
        int word = from >>> 6;
        if (word >= bits.length) {
            return -1;
        }
        long rest = bits[word] & -1L << from;
        while (true) {
            if (rest != 0) {
                return word * 64 + Long.numberOfTrailingZeros(rest);
            }
            if (++word == bits.length) {
                return -1;
            }
            rest = bits[word];
        }
    }
}
